// The PLY reader: the three encodings, the properties pbrt-v4 reads, and malformed files as
// errors at the Shape's location rather than crashes or huge allocations.
#include "geometry/ply_file.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

namespace caustica {
namespace {

const SourceLocation kLoc{"scene.pbrt", 3, 7};

MeshData read(const std::string &bytes) { return read_ply(bytes, "m.ply", kLoc); }

std::string error_of(const std::string &bytes) {
    try {
        read(bytes);
    } catch (const InputError &e) {
        EXPECT_EQ(e.location().line, 3);
        EXPECT_EQ(e.location().column, 7);
        return e.message();
    }
    ADD_FAILURE() << "no error";
    return {};
}

const std::string kAsciiHeader =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
const std::string kAsciiBody = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

const std::string kBinaryHeader =
    "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";

template <typename T> void put(std::string *out, T value, bool big_endian = false) {
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    if (big_endian)
        for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
    out->append(raw, sizeof(T));
}

// Three vertices and one triangle, the first vertex's x chosen by the caller.
std::string binary_triangle(float first_x, bool big_endian = false) {
    std::string s = kBinaryHeader;
    if (big_endian) s.replace(s.find("binary_little_endian"), 20, "binary_big_endian");
    const float p[9] = {first_x, 0, 0, 1, 0, 0, 0, 1, 0};
    for (float v : p) put(&s, v, big_endian);
    put<uint8_t>(&s, 3);
    for (int i : {0, 1, 2}) put<int32_t>(&s, i, big_endian);
    return s;
}

TEST(PlyFile, AsciiTriangle) {
    MeshData m = read(kAsciiHeader + kAsciiBody);
    ASSERT_EQ(m.p.size(), 3u);
    EXPECT_EQ(m.indices, (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(m.p[1].x, 1);
    EXPECT_TRUE(m.n.empty());
    EXPECT_TRUE(m.uv.empty());
}

// The file from pbrt-v4's scene collection that crashed Assimp: a binary body whose first byte
// is 0x0a, a line end. The float 0x3f80000a has that byte first in little-endian order.
TEST(PlyFile, BinaryBodyStartingWithALineEnd) {
    uint32_t bits = 0x3f80000a;
    float x;
    std::memcpy(&x, &bits, 4);
    std::string bytes = binary_triangle(x);
    ASSERT_EQ(bytes[kBinaryHeader.size()], '\n');
    MeshData m = read(bytes);
    ASSERT_EQ(m.p.size(), 3u);
    EXPECT_EQ(m.p[0].x, x);
    EXPECT_EQ(m.p[2].y, 1);
    EXPECT_EQ(m.indices, (std::vector<int>{0, 1, 2}));
}

TEST(PlyFile, BigEndianAndCrLfHeader) {
    MeshData big = read(binary_triangle(0.25f, true));
    EXPECT_EQ(big.p[0].x, 0.25f);
    EXPECT_EQ(big.p[1].x, 1);
    std::string body = binary_triangle(0.5f).substr(kBinaryHeader.size());
    std::string crlf;
    for (char c : kBinaryHeader) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    crlf += body;
    EXPECT_EQ(read(crlf).p[0].x, 0.5f);
}

TEST(PlyFile, NormalsUvQuadsAndOtherPropertiesAsPbrtReadsThem) {
    std::string s =
        "ply\nformat ascii 1.0\ncomment colours and face_indices are read past\n"
        "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
        "property uchar red\nproperty float nx\nproperty float ny\nproperty float nz\n"
        "property float s\nproperty float t\n"
        "element face 2\nproperty list uchar int vertex_indices\nproperty int face_indices\n"
        "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n"
        "0 0 0 255 0 0 1 0 0\n1 0 0 255 0 0 1 1 0\n1 1 0 255 0 0 1 1 1\n0 1 0 255 0 0 1 0 1\n"
        "4 0 1 2 3 7\n5 0 1 2 3 0 7\n0 1\n";
    MeshData m = read(s);
    EXPECT_EQ(m.n.size(), 4u);
    ASSERT_EQ(m.uv.size(), 4u);
    EXPECT_EQ(m.uv[2].x, 1);
    EXPECT_EQ(m.uv[3].y, 1);
    // The quad (v0, v1, v2, v3) is pbrt-v4's bilinear patch (v0, v1, v3, v2). The pentagon is
    // skipped, with a warning.
    EXPECT_TRUE(m.indices.empty());
    EXPECT_EQ(m.quads, (std::vector<int>{0, 1, 3, 2}));
}

TEST(PlyFile, CountsBeyondTheFileAreErrors) {
    std::string lying = kAsciiHeader;
    lying.replace(lying.find("vertex 3"), 8, "vertex 2000000000");
    EXPECT_NE(error_of(lying + kAsciiBody).find("2000000000 \"vertex\" elements"),
              std::string::npos);
    // The largest count a 64-bit number holds must not overflow the comparison.
    std::string huge = kAsciiHeader;
    huge.replace(huge.find("face 1"), 6, "face 18446744073709551615");
    EXPECT_NE(error_of(huge + kAsciiBody).find("\"face\" elements"), std::string::npos);
    // 3 vertices of 12 bytes and a face of at least 1 byte need 37 bytes.
    std::string binary = binary_triangle(0);
    EXPECT_NE(error_of(binary.substr(0, kBinaryHeader.size() + 36)).find("more than the 36"),
              std::string::npos);
    // A list longer than the rest of the file.
    std::string long_list = binary_triangle(0);
    long_list[kBinaryHeader.size() + 36] = char(200);
    EXPECT_NE(error_of(long_list).find("ends before"), std::string::npos);
}

TEST(PlyFile, MalformedFilesAreErrorsNotCrashes) {
    EXPECT_NE(error_of("ply\nnonsense\n").find("unknown keyword"), std::string::npos);
    EXPECT_NE(error_of("ply\nformat ascii 1.0\nelement vertex 99").find("end_header"),
              std::string::npos);
    EXPECT_NE(error_of("ply\nformat ascii 1.0\nelement vertex many\nend_header\n")
                  .find("not a number"),
              std::string::npos);
    EXPECT_NE(error_of(kAsciiHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n").find("vertex 3"),
              std::string::npos);
    EXPECT_NE(error_of(kAsciiHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n").find("vertex -1"),
              std::string::npos);
    EXPECT_NE(error_of(kAsciiHeader + "0 0 0\n1 0 x\n0 1 0\n3 0 1 2\n").find("not a number"),
              std::string::npos);
    std::string no_z = kAsciiHeader;
    no_z.replace(no_z.find("property float z\n"), 17, "");
    EXPECT_NE(error_of(no_z + kAsciiBody).find("lacks x, y or z"), std::string::npos);
}

TEST(PlyFile, Magic) {
    EXPECT_TRUE(is_ply("ply\nformat ascii 1.0\n"));
    EXPECT_TRUE(is_ply("ply\r\nformat ascii 1.0\r\n"));
    EXPECT_FALSE(is_ply("o cube\nv 0 0 0\n"));
    EXPECT_FALSE(is_ply("pl"));
}

} // namespace
} // namespace caustica
