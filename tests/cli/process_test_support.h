// Starting `caustica` (or a launcher that starts it) as a child process that a test can signal
// and wait for, and comparing its images bit for bit.
#pragma once

#include "../integrators/render_test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <fcntl.h>
#include <spawn.h>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <vector>

extern char **environ;

namespace caustica::testing {

// Starts `program` with `args`, its standard error going to the file `log`.
inline pid_t start_process(const std::string &program, std::vector<std::string> args, const std::string &log) {
    args.insert(args.begin(), program);
    std::vector<char *> argv;
    for (std::string &a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid = -1;
    EXPECT_EQ(posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ), 0);
    posix_spawn_file_actions_destroy(&actions);
    return pid;
}

inline pid_t start_caustica(std::vector<std::string> args, const std::string &log) {
    return start_process(CAUSTICA_BINARY, std::move(args), log);
}

// The exit status, or 1000 + the signal that ended the process.
inline int wait_for(pid_t pid) {
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
}

// Waits until `predicate` holds or the process has ended; true if it holds.
template <typename Predicate> bool wait_until(pid_t pid, Predicate predicate) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (std::chrono::steady_clock::now() < deadline) {
        if (predicate()) return true;
        int status = 0;
        if (waitpid(pid, &status, WNOHANG) == pid) return predicate();
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return false;
}

inline bool bit_identical(const RgbImage &a, const RgbImage &b) {
    return a.width == b.width && a.height == b.height && a.rgb.size() == b.rgb.size() &&
           std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)) == 0;
}

} // namespace caustica::testing
