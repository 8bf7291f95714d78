// Helpers shared by the parser tests.
#pragma once

#include "parser/scene_description.h"

#include <gtest/gtest.h>

#include <string>

namespace caustica::test {

// Parses text with warnings silenced (they are still recorded in SceneDescription::warnings).
inline SceneDescription parse(const std::string &text) {
    set_warnings_enabled(false);
    SceneDescription d = parse_scene_string(text, "test.pbrt");
    set_warnings_enabled(true);
    return d;
}

// The InputError that parsing `text` throws; fails the test if none is thrown.
inline InputError parse_error(const std::string &text) {
    set_warnings_enabled(false);
    try {
        parse_scene_string(text, "test.pbrt");
    } catch (const InputError &e) {
        set_warnings_enabled(true);
        return e;
    }
    set_warnings_enabled(true);
    ADD_FAILURE() << "expected an InputError for:\n" << text;
    return InputError("no error");
}

inline void expect_near(Vec3f a, Vec3f b, float tol = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, tol) << "x";
    EXPECT_NEAR(a.y, b.y, tol) << "y";
    EXPECT_NEAR(a.z, b.z, tol) << "z";
}

} // namespace caustica::test
