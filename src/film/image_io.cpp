#include "film/image_io.h"

#include "openimageio/openimageio_plugin.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <Imath/half.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>

namespace caustica {

namespace {

std::runtime_error write_error(const std::string &path, const std::string &reason) {
    return std::runtime_error("cannot write image \"" + path + "\": " + reason);
}

// Runs `write` on a fresh temporary file next to `path` and renames the result onto `path`.
// The temporary keeps the destination's extension, for libraries that pick the format by it.
void write_atomically(const std::string &path, const std::function<void(const std::string &)> &write) {
    namespace fs = std::filesystem;
    fs::path target(path);
    fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::string ext = target.extension().string();
    // A hidden name ("." prefix) keeps the temporary out of directory listings.
    std::string hidden(1, '.');
    hidden.append(target.filename().string()).append(".tmp-XXXXXX").append(ext);
    std::string pattern = (dir / hidden).string();
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    int fd = mkstemps(name.data(), int(ext.size()));
    if (fd < 0) throw write_error(path, std::strerror(errno));
    // mkstemps creates the file readable by its owner only; give the image the permissions a
    // newly created file would have.
    mode_t mask = umask(0);
    umask(mask);
    fchmod(fd, 0666 & ~mask);
    close(fd);
    std::string tmp(name.data());
    try {
        write(tmp);
    } catch (const std::exception &e) {
        std::remove(tmp.c_str());
        throw write_error(path, e.what());
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        int err = errno;
        std::remove(tmp.c_str());
        throw write_error(path, std::strerror(err));
    }
}

void check_image(const std::string &path, const Image &image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.rgb.size() != size_t(image.width) * image.height * 3)
        throw write_error(path, "the image is empty or inconsistent");
    for (const Image::Layer &layer : image.layers)
        if (layer.rgb.size() != image.rgb.size())
            throw write_error(path, "layer \"" + layer.name + "\" does not match the image size");
    for (const Image::Channel &channel : image.channels)
        if (channel.values.size() != size_t(image.width) * image.height)
            throw write_error(path, "channel \"" + channel.name + "\" does not match the image size");
}

} // namespace

void write_exr(const std::string &path, const Image &image,
               const std::map<std::string, std::string> &metadata, ExrPixelType pixel_type) {
    check_image(path, image);
    Vec2i full = image.full_resolution;
    if (full.x <= 0 || full.y <= 0) full = {image.width, image.height};
    Imath::Box2i display({0, 0}, {full.x - 1, full.y - 1});
    Imath::Box2i data({image.origin.x, image.origin.y},
                      {image.origin.x + image.width - 1, image.origin.y + image.height - 1});

    write_atomically(path, [&](const std::string &tmp) {
        Imf::Header header(display, data);
        header.compression() = Imf::ZIP_COMPRESSION;
        for (const auto &[key, value] : metadata) header.insert(key, Imf::StringAttribute(value));
        const char *names[3] = {"R", "G", "B"};
        Imf::FrameBuffer fb;
        std::vector<Imath::half> half_pixels;
        // The single channels as half floats, when asked for.
        std::vector<std::vector<Imath::half>> half_channels;
        if (pixel_type == ExrPixelType::Half) {
            half_pixels.resize(image.rgb.size());
            for (size_t i = 0; i < image.rgb.size(); ++i)
                half_pixels[i] = Imath::half(std::min(image.rgb[i], 65504.f));
            for (const Image::Channel &channel : image.channels) {
                std::vector<Imath::half> &h = half_channels.emplace_back(channel.values.size());
                for (size_t i = 0; i < h.size(); ++i) h[i] = Imath::half(clamp(channel.values[i], -65504.f, 65504.f));
            }
        }
        for (int c = 0; c < 3; ++c) {
            if (pixel_type == ExrPixelType::Half) {
                header.channels().insert(names[c], Imf::Channel(Imf::HALF));
                fb.insert(names[c], Imf::Slice::Make(Imf::HALF, half_pixels.data() + c, data,
                                                     3 * sizeof(Imath::half)));
            } else {
                header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
                fb.insert(names[c], Imf::Slice::Make(Imf::FLOAT, image.rgb.data() + c, data,
                                                     3 * sizeof(float)));
            }
        }
        for (const Image::Layer &layer : image.layers)
            for (int c = 0; c < 3; ++c) {
                std::string channel = layer.name + "." + names[c];
                header.channels().insert(channel, Imf::Channel(Imf::FLOAT));
                fb.insert(channel, Imf::Slice::Make(Imf::FLOAT, layer.rgb.data() + c, data, 3 * sizeof(float)));
            }
        for (size_t i = 0; i < image.channels.size(); ++i) {
            const std::string &name = image.channels[i].name;
            if (pixel_type == ExrPixelType::Half) {
                header.channels().insert(name, Imf::Channel(Imf::HALF));
                fb.insert(name, Imf::Slice::Make(Imf::HALF, half_channels[i].data(), data, sizeof(Imath::half)));
            } else {
                header.channels().insert(name, Imf::Channel(Imf::FLOAT));
                fb.insert(name, Imf::Slice::Make(Imf::FLOAT, image.channels[i].values.data(), data, sizeof(float)));
            }
        }
        Imf::OutputFile file(tmp.c_str(), header);
        file.setFrameBuffer(fb);
        file.writePixels(image.height);
    });
}

Image read_exr(const std::string &path, std::map<std::string, std::string> *metadata) {
    try {
        Imf::InputFile file(path.c_str());
        const Imf::Header &header = file.header();
        Imath::Box2i data = header.dataWindow(), display = header.displayWindow();
        Image image(data.max.x - data.min.x + 1, data.max.y - data.min.y + 1);
        image.origin = {data.min.x - display.min.x, data.min.y - display.min.y};
        image.full_resolution = {display.max.x - display.min.x + 1, display.max.y - display.min.y + 1};

        const Imf::ChannelList &channels = header.channels();
        bool rgb = channels.findChannel("R") || channels.findChannel("G") || channels.findChannel("B");
        bool grey = !rgb && channels.findChannel("Y");
        if (!rgb && !grey) throw std::runtime_error("no R, G, B or Y channel");
        Imf::FrameBuffer fb;
        const char *names[3] = {"R", "G", "B"};
        for (int c = 0; c < (grey ? 1 : 3); ++c)
            fb.insert(grey ? "Y" : names[c],
                      Imf::Slice::Make(Imf::FLOAT, image.rgb.data() + c, data, 3 * sizeof(float)));
        // Layers: every NAME with NAME.R, NAME.G and NAME.B channels.
        for (auto it = channels.begin(); it != channels.end(); ++it) {
            std::string name = it.name();
            if (name.size() < 3 || name.compare(name.size() - 2, 2, ".R") != 0) continue;
            std::string layer = name.substr(0, name.size() - 2);
            if (!channels.findChannel(layer + ".G") || !channels.findChannel(layer + ".B")) continue;
            image.layers.push_back({layer, std::vector<float>(image.rgb.size())});
        }
        for (Image::Layer &layer : image.layers)
            for (int c = 0; c < 3; ++c)
                fb.insert(layer.name + "." + names[c],
                          Imf::Slice::Make(Imf::FLOAT, layer.rgb.data() + c, data, 3 * sizeof(float)));
        // Every other channel on its own.
        auto in_layer = [&](const std::string &name) {
            for (const Image::Layer &layer : image.layers)
                if (name.size() == layer.name.size() + 2 && name.compare(0, layer.name.size() + 1, layer.name + ".") == 0 &&
                    std::strchr("RGB", name.back()))
                    return true;
            return false;
        };
        for (auto it = channels.begin(); it != channels.end(); ++it) {
            const std::string name = it.name();
            if (name == "R" || name == "G" || name == "B" || (grey && name == "Y") || in_layer(name)) continue;
            image.channels.push_back({name, std::vector<float>(size_t(image.width) * image.height)});
        }
        for (Image::Channel &channel : image.channels)
            fb.insert(channel.name, Imf::Slice::Make(Imf::FLOAT, channel.values.data(), data, sizeof(float)));
        file.setFrameBuffer(fb);
        file.readPixels(data.min.y, data.max.y);
        if (metadata)
            for (auto it = header.begin(); it != header.end(); ++it)
                if (auto *text = dynamic_cast<const Imf::StringAttribute *>(&it.attribute()))
                    (*metadata)[it.name()] = text->value();
        if (grey)
            for (size_t i = 0; i < image.rgb.size(); i += 3) image.rgb[i + 1] = image.rgb[i + 2] = image.rgb[i];
        return image;
    } catch (const std::exception &e) {
        throw std::runtime_error("cannot read image \"" + path + "\": " + e.what());
    }
}

float srgb_encode(float v) {
    if (v <= 0.0031308f) return 12.92f * v;
    return 1.055f * std::pow(v, 1 / 2.4f) - 0.055f;
}

uint8_t tone_map_clamp_srgb8(float v) {
    if (!(v > 0)) return 0;   // also NaN
    if (v >= 1) return 255;
    return uint8_t(clamp(std::lround(255 * srgb_encode(v)), 0l, 255l));
}

void write_png(const std::string &path, const Image &image) {
    check_image(path, image);
    std::vector<uint8_t> pixels(image.rgb.size());
    for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = tone_map_clamp_srgb8(image.rgb[i]);
    write_atomically(path, [&](const std::string &tmp) {
        std::string why = openimageio().write_rgb8(tmp, image.width, image.height, pixels.data());
        if (!why.empty()) throw std::runtime_error(why);
    });
}

} // namespace caustica
