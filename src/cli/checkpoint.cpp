#include "cli/checkpoint.h"

#include "cli/render_session.h"
#include "core/error.h"
#include "core/rng.h"
#include "film/film.h"
#include "parser/scene_description.h"
#include "scene/scene.h"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

#include <fcntl.h>
#include <unistd.h>

namespace caustica {

namespace {

constexpr const char *kFormatLine = "caustica checkpoint 2";
constexpr const char *kEndMarker = "end of checkpoint\n";

// A 64-bit hash of byte strings, to notice that a file has changed (not against tampering):
// every 8-byte word goes through a bijective mix, so any change of a single word changes the
// result.
class ContentHash {
  public:
    void add(const char *data, size_t size) {
        for (size_t i = 0; i < size; ++i) {
            word_ |= uint64_t(uint8_t(data[i])) << (8 * filled_);
            if (++filled_ == 8) flush_word();
        }
        length_ += size;
    }
    // Adds a file's contents; false if it cannot be read.
    bool add_file(const std::string &path) {
        std::ifstream in(path, std::ios::binary);
        if (!in) return false;
        std::vector<char> buffer(1 << 20);
        while (in) {
            in.read(buffer.data(), std::streamsize(buffer.size()));
            add(buffer.data(), size_t(in.gcount()));
        }
        // Separates files, so that moving bytes from one file to the next is a change.
        const uint64_t size = length_;
        if (filled_ > 0) flush_word();
        h_ = mix_bits(h_ ^ size);
        return in.eof();
    }
    std::string hex() const {
        char text[17];
        std::snprintf(text, sizeof text, "%016llx", (unsigned long long)mix_bits(h_ ^ length_));
        return text;
    }

  private:
    void flush_word() {
        h_ = mix_bits(h_ ^ word_);
        word_ = 0;
        filled_ = 0;
    }
    uint64_t h_ = 0x9e3779b97f4a7c15ULL, word_ = 0, length_ = 0;
    int filled_ = 0;
};

// The files a scene consists of, by path: those its directives come from, and those that its
// parameters name. A string parameter naming an existing file is taken to be read, which covers
// meshes, images and spectra without listing parameter names; the film's parameters are skipped,
// as its "filename" is the output (which a resumed render rewrites), as is the MSE reference
// image an option may write.
class SceneFiles {
  public:
    void add_entity(const SceneEntity &entity) { add(entity.loc, entity.params, true); }
    void add(const SourceLocation &loc, const ParameterDictionary &params, bool named_files) {
        add_path(loc.file);
        for (const ParsedParameter &p : params.parameters()) {
            add_path(p.loc.file);
            if (!named_files || (p.type != "string" && p.type != "spectrum") || p.name == "msereferenceout")
                continue;
            for (const std::string &value : p.strings) add_path(params.file_path(p.name, value));
        }
    }
    const std::set<std::string> &paths() const { return paths_; }

  private:
    void add_path(const std::string &path) {
        std::error_code ec;
        if (!path.empty() && std::filesystem::is_regular_file(path, ec)) paths_.insert(path);
    }
    std::set<std::string> paths_;
};

std::string scene_files_hash(const std::string &scene_path, const SceneDescription &d) {
    SceneFiles files;
    files.add({scene_path, 0, 0}, ParameterDictionary(), false);
    files.add(d.film.loc, d.film.params, false);
    for (const SceneEntity *e : {&d.sampler, &d.integrator, &d.filter, &d.accelerator,
                                 static_cast<const SceneEntity *>(&d.camera)})
        files.add_entity(*e);
    files.add(d.options.directive_location(), d.options, true);
    for (const SceneEntity &e : d.materials) files.add_entity(e);
    for (const auto &[name, e] : d.named_materials) files.add_entity(e);
    for (const TextureEntity &e : d.textures) files.add_entity(e);
    for (const LightEntity &e : d.lights) files.add_entity(e);
    for (const SceneEntity &e : d.area_lights) files.add_entity(e);
    for (const ShapeEntity &e : d.shapes) files.add_entity(e);
    for (const MediumEntity &e : d.media) files.add_entity(e);
    for (const InstanceDefinition &instance : d.instances)
        for (const ShapeEntity &e : instance.shapes) files.add_entity(e);
    ContentHash hash;
    for (const std::string &path : files.paths())
        if (!hash.add_file(path)) throw InputError("cannot read \"" + path + "\" to fingerprint the scene");
    return hash.hex();
}

// The running executable's contents: results may change with any change to the code.
std::string build_hash() {
    ContentHash hash;
    if (!hash.add_file("/proc/self/exe")) throw std::runtime_error("cannot read the caustica executable");
    return hash.hex();
}

std::string number_text(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

template <typename T> void write_value(std::ostream &out, T value) {
    out.write(reinterpret_cast<const char *>(&value), sizeof value);
}

template <typename T> T read_value(std::istream &in) {
    T value{};
    in.read(reinterpret_cast<char *>(&value), sizeof value);
    if (!in) throw std::runtime_error("truncated");
    return value;
}

void write_header(std::ostream &out, const RenderFingerprint &fingerprint) {
    out << kFormatLine << '\n';
    for (const auto &[name, value] : fingerprint.fields) out << name << ' ' << value << '\n';
    out << '\n';
}

void write_stats(std::ostream &out, const RenderStats &stats) {
    write_value<int64_t>(out, stats.samples_per_pixel);
    write_value<uint64_t>(out, stats.pixel_samples.load());
    write_value<uint64_t>(out, stats.rays.load());
    write_value<uint64_t>(out, stats.non_finite_samples.load());
    write_value<double>(out, stats.seconds);
    write_value<uint64_t>(out, stats.pixel_sample_counts.size());
    out.write(reinterpret_cast<const char *>(stats.pixel_sample_counts.data()),
              std::streamsize(stats.pixel_sample_counts.size() * sizeof(int)));
}

void read_stats(std::istream &in, size_t pixel_count, RenderStats &stats) {
    const int64_t spp = read_value<int64_t>(in);
    const uint64_t pixel_samples = read_value<uint64_t>(in), rays = read_value<uint64_t>(in),
                   non_finite = read_value<uint64_t>(in);
    const double seconds = read_value<double>(in);
    const uint64_t counts = read_value<uint64_t>(in);
    if (spp < 0 || spp > INT32_MAX || (counts != 0 && counts != pixel_count) || !(seconds >= 0))
        throw std::runtime_error("inconsistent sample counts");
    std::vector<int> pixel_sample_counts(counts);
    in.read(reinterpret_cast<char *>(pixel_sample_counts.data()), std::streamsize(counts * sizeof(int)));
    if (!in) throw std::runtime_error("truncated");
    stats.samples_per_pixel = int(spp);
    stats.pixel_samples = pixel_samples;
    stats.rays = rays;
    stats.non_finite_samples = non_finite;
    stats.seconds = seconds;
    stats.pixel_sample_counts = std::move(pixel_sample_counts);
}

// "checkpoint X belongs to a different render: ..." naming every field that differs.
std::string mismatch_message(const std::string &path, const RenderFingerprint &saved,
                             const RenderFingerprint &current) {
    std::string differences;
    for (const auto &[name, value] : current.fields) {
        std::string saved_value = "(none)";
        for (const auto &[saved_name, v] : saved.fields)
            if (saved_name == name) saved_value = v;
        if (saved_value == value) continue;
        if (!differences.empty()) differences += "; ";
        if (name == "build") differences += "it was written by a different build of caustica";
        else if (name == "scene") differences += "the scene or a file it reads has changed";
        else differences += name + " is " + saved_value + " there, " + value + " here";
    }
    return "checkpoint \"" + path + "\" belongs to a different render: " + differences +
           " (--resume continues only the same command line)";
}

void sync_to_disk(const std::string &path, int flags) {
    int fd = ::open(path.c_str(), flags);
    if (fd < 0) throw std::runtime_error("cannot open \"" + path + "\" to flush it: " + std::strerror(errno));
    int result = ::fsync(fd);
    ::close(fd);
    if (result != 0) throw std::runtime_error("cannot flush \"" + path + "\": " + std::strerror(errno));
}

} // namespace

RenderFingerprint render_fingerprint(const std::string &scene_path, const SceneDescription &description,
                                     const Scene &scene, const RenderBudget &budget, bool variance) {
    const Film &film = *scene.film;
    const PixelBounds &bounds = film.pixel_bounds();
    auto vec = [](Vec2i v) { return std::to_string(v.x) + " " + std::to_string(v.y); };
    return {{
        {"build", build_hash()},
        {"scene", scene_files_hash(scene_path, description)},
        {"integrator", scene.integrator_name},
        {"seed", std::to_string(scene.overrides.seed)},
        {"spp", std::to_string(budget.spp)},
        {"time", number_text(budget.seconds)},
        {"resolution", vec(film.resolution())},
        {"pixel-bounds", vec(bounds.min) + " " + vec(bounds.max)},
        {"wavelength", number_text(scene.overrides.wavelength)},
        {"single-wavelength", scene.overrides.single_wavelength ? "on" : "off"},
        {"spectral", scene.overrides.spectral ? "on" : "off"},
        {"variance", variance ? "on" : "off"},
    }};
}

std::string checkpoint_path(const std::string &output_path) { return output_path + ".checkpoint"; }

std::string session_state(const RenderSession &session, const RenderStats &stats) {
    std::ostringstream out;
    write_stats(out, stats);
    session.scene->film->save_state(out);
    std::ostringstream integrator_state;
    session.integrator->save_state(integrator_state);
    const std::string state = std::move(integrator_state).str();
    write_value<uint64_t>(out, state.size());
    out.write(state.data(), std::streamsize(state.size()));
    return std::move(out).str();
}

CheckpointFile::CheckpointFile(const std::string &path, const RenderFingerprint &fingerprint, size_t states)
    : path_(path), temporary_(path + ".tmp"), out_(temporary_, std::ios::binary | std::ios::trunc), remaining_(states) {
    if (!out_) throw std::runtime_error("cannot create \"" + temporary_ + "\": " + std::strerror(errno));
    write_header(out_, fingerprint);
    write_value<uint64_t>(out_, states);
}

CheckpointFile::~CheckpointFile() {
    if (!committed_) {
        out_.close();
        std::remove(temporary_.c_str());
    }
}

void CheckpointFile::add(const std::string &state) {
    if (remaining_ == 0) throw std::logic_error("checkpoint: more states than announced");
    --remaining_;
    write_value<uint64_t>(out_, state.size());
    out_.write(state.data(), std::streamsize(state.size()));
}

void CheckpointFile::commit() {
    if (remaining_ != 0) throw std::logic_error("checkpoint: fewer states than announced");
    out_ << kEndMarker;
    out_.close();
    if (!out_) throw std::runtime_error("failed writing \"" + temporary_ + "\"");
    // On the disk before it replaces the previous checkpoint, and the rename on the disk too.
    sync_to_disk(temporary_, O_RDONLY);
    if (std::rename(temporary_.c_str(), path_.c_str()) != 0)
        throw std::runtime_error("cannot rename \"" + temporary_ + "\" to \"" + path_ + "\": " + std::strerror(errno));
    committed_ = true;
    std::filesystem::path directory = std::filesystem::path(path_).parent_path();
    sync_to_disk(directory.empty() ? "." : directory.string(), O_RDONLY | O_DIRECTORY);
}

CheckpointReader::CheckpointReader(const std::string &path, const RenderFingerprint &fingerprint)
    : path_(path), in_(path, std::ios::binary) {
    if (!in_)
        throw InputError("--resume: there is no checkpoint \"" + path +
                         "\" (--checkpoint writes it next to the output; it is deleted when the render completes)");
    std::string line;
    if (!std::getline(in_, line) || line != kFormatLine) throw damaged("not a caustica checkpoint of this version");
    RenderFingerprint saved;
    while (std::getline(in_, line) && !line.empty()) {
        const size_t space = line.find(' ');
        if (space == std::string::npos) throw damaged("bad header line \"" + line + "\"");
        saved.fields.emplace_back(line.substr(0, space), line.substr(space + 1));
    }
    if (!in_) throw damaged("truncated header");
    if (saved.fields != fingerprint.fields) throw InputError(mismatch_message(path, saved, fingerprint));
    // The states' sizes and the end marker are checked now, skipping over the states, so that
    // reading them one at a time (next_state) cannot fail part-way.
    try {
        const uint64_t count = read_value<uint64_t>(in_);
        if (count == 0 || count > (uint64_t(1) << 24)) throw damaged("bad rank count");
        states_ = size_t(count);
        first_state_ = in_.tellg();
        for (size_t r = 0; r < states_; ++r) {
            const uint64_t size = read_value<uint64_t>(in_);
            if (size > (uint64_t(1) << 40)) throw damaged("bad state size");
            in_.seekg(std::streamoff(size), std::ios::cur);
        }
        std::string end(std::strlen(kEndMarker), '\0');
        in_.read(end.data(), std::streamsize(end.size()));
        if (!in_ || end != kEndMarker || in_.peek() != std::char_traits<char>::eof()) throw damaged("no end marker");
    } catch (const InputError &) {
        throw;
    } catch (const std::runtime_error &e) {
        throw damaged(e.what());
    }
    in_.clear();
    in_.seekg(first_state_);
}

InputError CheckpointReader::damaged(const std::string &why) const {
    return InputError("checkpoint \"" + path_ + "\" is damaged (" + why + "); delete it to start afresh");
}

std::string CheckpointReader::next_state() {
    const uint64_t size = read_value<uint64_t>(in_);
    std::string state(size_t(size), '\0');
    in_.read(state.data(), std::streamsize(state.size()));
    if (!in_) throw damaged("truncated");
    return state;
}

void restore_session_state(const std::string &state, RenderSession &session, RenderStats &stats) {
    std::istringstream in(state);
    const PixelBounds &bounds = session.scene->film->pixel_bounds();
    const size_t pixel_count = size_t(bounds.width()) * bounds.height();
    RenderStats restored;
    read_stats(in, pixel_count, restored);
    session.scene->film->restore_state(in);
    const uint64_t state_size = read_value<uint64_t>(in);
    std::string integrator(state_size <= (uint64_t(1) << 40) ? size_t(state_size) : 0, '\0');
    if (integrator.size() != state_size) throw std::runtime_error("bad integrator state size");
    in.read(integrator.data(), std::streamsize(integrator.size()));
    if (!in || in.peek() != std::char_traits<char>::eof()) throw std::runtime_error("truncated");
    std::istringstream integrator_state(std::move(integrator));
    session.integrator->restore_state(integrator_state);
    stats.samples_per_pixel = restored.samples_per_pixel;
    stats.pixel_samples = restored.pixel_samples.load();
    stats.rays = restored.rays.load();
    stats.non_finite_samples = restored.non_finite_samples.load();
    stats.seconds = restored.seconds;
    stats.pixel_sample_counts = std::move(restored.pixel_sample_counts);
}

void resume_from_checkpoint(const std::string &path, const RenderFingerprint &fingerprint, const ProcessGroup &group,
                            RenderSession &session, RenderStats &stats) {
    // Rank 0 reads the file; every rank learns whether that worked, so that an error ends
    // every rank the same way rather than leaving the others waiting.
    std::optional<CheckpointReader> reader;
    std::string error;
    if (group.rank() == 0) {
        try {
            reader.emplace(path, fingerprint);
            if (reader->states() != size_t(group.ranks()))
                throw InputError("checkpoint \"" + path + "\" was written by " + std::to_string(reader->states()) +
                                 " processes, and this render has " + std::to_string(group.ranks()) +
                                 " (resume with the same number of MPI ranks)");
        } catch (const InputError &e) {
            error = e.message();
        }
    }
    std::vector<char> error_bytes(error.begin(), error.end());
    error_bytes = group.gather_all(std::move(error_bytes));
    if (!error_bytes.empty()) throw InputError(std::string(error_bytes.begin(), error_bytes.end()));
    const std::string mine = group.scatter_from_root([&](int) { return reader->next_state(); });
    try {
        restore_session_state(mine, session, stats);
    } catch (const std::runtime_error &e) {
        throw InputError("checkpoint \"" + path + "\" is damaged (" + e.what() + "); delete it to start afresh");
    } catch (const std::bad_alloc &) {
        throw InputError("checkpoint \"" + path + "\" is damaged (impossible sizes); delete it to start afresh");
    }
}

CheckpointWriter::CheckpointWriter(std::string path, RenderFingerprint fingerprint, double interval,
                                   const RenderSession &session, const RenderStats &stats,
                                   const std::atomic<bool> *interrupt, const ProcessGroup &group)
    : path_(std::move(path)), fingerprint_(std::move(fingerprint)), interval_(interval), session_(session),
      stats_(stats), interrupt_(interrupt), group_(group), last_(std::chrono::steady_clock::now()) {}

void CheckpointWriter::at_boundary() {
    // Every rank is at the same boundary: rank 0's clock and signal decide for all.
    const bool interrupted = interrupt_ && interrupt_->load(std::memory_order_relaxed);
    const auto now = std::chrono::steady_clock::now();
    bool due = interrupted || std::chrono::duration<double>(now - last_).count() >= interval_;
    // The same state again (a renderer may report it twice): nothing new to save.
    if (stats_.samples_per_pixel == saved_spp_ && stats_.pixel_samples == saved_pixel_samples_) due = false;
    if (!group_.agree(due)) return;
    // Rank 0 writes the states as they arrive, one at a time.
    try {
        std::optional<CheckpointFile> file;
        if (group_.rank() == 0) file.emplace(path_, fingerprint_, size_t(group_.ranks()));
        group_.gather_to_root(session_state(session_, stats_), [&](const std::string &state) { file->add(state); });
        if (file) {
            file->commit();
            saved_spp_ = stats_.samples_per_pixel;
            saved_pixel_samples_ = stats_.pixel_samples;
            saved_partial_ = !stats_.pixel_sample_counts.empty();
        }
    } catch (const std::runtime_error &e) {
        warning(std::string(e.what()) + "; the render goes on without this checkpoint");
    }
    last_ = std::chrono::steady_clock::now();
}

} // namespace caustica
