// Mitsuba's "tensor file", the container of the RGL BSDF files (materials/measured_bxdf.h): named
// arrays of any rank, each of one numeric type. Layout (little-endian): the 12 bytes
// "tensor_file\0", the version (1, 0), the number of fields (uint32), then per field its name
// (uint16 length and bytes), rank (uint16), type (uint8: 1 uint8, 2 int8, 3 uint16, 4 int16,
// 5 uint32, 6 int32, 7 uint64, 8 int64, 9 float16, 10 float32, 11 float64), the offset of its data
// in the file (uint64) and its size along each dimension (uint64 each).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace caustica {

struct TensorField {
    enum Type : uint8_t { UInt8 = 1, Int8, UInt16, Int16, UInt32, Int32, UInt64, Int64, Float16, Float32, Float64 };
    Type type;
    std::vector<uint64_t> shape;
    std::string bytes;  // the data as stored

    uint64_t count() const;  // the number of elements
    // The elements of a Float32 field.
    std::vector<float> floats() const;
};

// The fields of the tensor file at path. Throws InputError (without a location: the caller
// knows which parameter named the file) when the file cannot be read or is not a well-formed
// tensor file: a wrong header or version, an unknown type, a field whose data lies beyond the
// end of the file, or a repeated name.
std::map<std::string, TensorField> read_tensor_file(const std::string &path);

} // namespace caustica
