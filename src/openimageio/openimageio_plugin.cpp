#include "openimageio/openimageio_plugin.h"

#include <dlfcn.h>

#include <filesystem>
#include <stdexcept>

namespace caustica {

namespace {

const OpenImageIOPlugin *load_plugin() {
    namespace fs = std::filesystem;
    // Beside the executable first (an installed or copied build), then where the build put it.
    std::vector<std::string> candidates;
    std::error_code error;
    fs::path executable = fs::read_symlink("/proc/self/exe", error);
    if (!error) candidates.push_back((executable.parent_path() / CAUSTICA_OPENIMAGEIO_PLUGIN_NAME).string());
    candidates.push_back(CAUSTICA_OPENIMAGEIO_PLUGIN_PATH);

    std::string reasons;
    for (const std::string &path : candidates) {
        if (!fs::exists(path)) {
            reasons += "\n  " + path + ": no such file";
            continue;
        }
        void *library = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!library) {
            reasons += "\n  " + path + ": " + dlerror();
            continue;
        }
        using Entry = const OpenImageIOPlugin *(*)();
        auto entry = reinterpret_cast<Entry>(dlsym(library, "caustica_openimageio_plugin"));
        if (entry) return entry();
        reasons += "\n  " + path + ": no entry point caustica_openimageio_plugin";
    }
    throw std::runtime_error("cannot load the OpenImageIO plugin, which PNG output and image "
                             "files need; tried:" + reasons);
}

} // namespace

int DecodedImage::channel_index(const std::string &name) const {
    for (size_t c = 0; c < channel_names.size(); ++c)
        if (channel_names[c] == name) return int(c);
    return -1;
}

const OpenImageIOPlugin &openimageio() {
    static const OpenImageIOPlugin *plugin = load_plugin();
    return *plugin;
}

DecodedImage read_image_file(const std::string &path) {
    DecodedImage image;
    std::string why = openimageio().read_image(path, &image);
    if (!why.empty()) throw std::runtime_error("cannot read image \"" + path + "\": " + why);
    return image;
}

} // namespace caustica
