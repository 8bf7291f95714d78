#include "materials/tensor_file.h"

#include "core/error.h"
#include "core/file_contents.h"

#include <cstring>

namespace caustica {

namespace {

uint64_t type_size(TensorField::Type type) {
    switch (type) {
    case TensorField::UInt8:
    case TensorField::Int8: return 1;
    case TensorField::UInt16:
    case TensorField::Int16:
    case TensorField::Float16: return 2;
    case TensorField::UInt32:
    case TensorField::Int32:
    case TensorField::Float32: return 4;
    case TensorField::UInt64:
    case TensorField::Int64:
    case TensorField::Float64: return 8;
    }
    return 0;
}

// Reads little-endian values from the file's bytes, failing at its end.
class Reader {
  public:
    Reader(const std::string &bytes, const std::string &path) : bytes_(bytes), path_(path) {}
    template <typename T>
    T read(const char *what) {
        T value;
        if (bytes_.size() - pos_ < sizeof(T)) fail(std::string("it ends inside ") + what);
        std::memcpy(&value, bytes_.data() + pos_, sizeof(T));
        pos_ += sizeof(T);
        return value;
    }
    std::string read_bytes(size_t n, const char *what) {
        if (bytes_.size() - pos_ < n) fail(std::string("it ends inside ") + what);
        pos_ += n;
        return bytes_.substr(pos_ - n, n);
    }
    [[noreturn]] void fail(const std::string &why) const {
        throw InputError("\"" + path_ + "\" is not a tensor file (RGL BSDF): " + why);
    }

  private:
    const std::string &bytes_;
    const std::string &path_;
    size_t pos_ = 0;
};

} // namespace

uint64_t TensorField::count() const {
    uint64_t n = 1;
    for (uint64_t s : shape) n *= s;
    return n;
}

std::vector<float> TensorField::floats() const {
    std::vector<float> values(bytes.size() / sizeof(float));
    std::memcpy(values.data(), bytes.data(), values.size() * sizeof(float));
    return values;
}

std::map<std::string, TensorField> read_tensor_file(const std::string &path) {
    std::string error;
    std::optional<std::string> contents = read_file_contents(path, &error);
    if (!contents) throw InputError("cannot read \"" + path + "\": " + error);
    const std::string &bytes = *contents;
    Reader in(bytes, path);

    if (in.read_bytes(12, "its header") != std::string("tensor_file\0", 12)) in.fail("its header is wrong");
    const auto major = in.read<uint8_t>("its version"), minor = in.read<uint8_t>("its version");
    if (major != 1 || minor != 0)
        in.fail("version " + std::to_string(major) + "." + std::to_string(minor) + " is not 1.0");
    const auto n_fields = in.read<uint32_t>("its field count");

    std::map<std::string, TensorField> fields;
    for (uint32_t f = 0; f < n_fields; ++f) {
        const auto name_length = in.read<uint16_t>("a field's name");
        std::string name = in.read_bytes(name_length, "a field's name");
        const auto rank = in.read<uint16_t>("a field's rank");
        const auto type = in.read<uint8_t>("a field's type");
        const auto offset = in.read<uint64_t>("a field's offset");
        TensorField field{TensorField::Type(type), {}, {}};
        const uint64_t element = type_size(field.type);
        if (element == 0) in.fail("field \"" + name + "\" has the unknown type " + std::to_string(type));
        // The size in bytes, which must fit in the file (so no product can overflow first).
        uint64_t size = element;
        for (uint16_t d = 0; d < rank; ++d) {
            const auto extent = in.read<uint64_t>("a field's shape");
            field.shape.push_back(extent);
            if (extent != 0 && size > bytes.size() / extent) size = bytes.size() + 1;
            else size *= extent;
        }
        if (size > bytes.size() || offset > bytes.size() - size)
            in.fail("the data of field \"" + name + "\" lies beyond the end of the file");
        field.bytes = bytes.substr(offset, size);
        if (!fields.emplace(name, std::move(field)).second) in.fail("field \"" + name + "\" appears twice");
    }
    return fields;
}

} // namespace caustica
