// The PLY header check that runs before Assimp allocates the element counts a header declares.
#include "geometry/ply_header.h"

#include <gtest/gtest.h>

#include <string>

namespace caustica {
namespace {

const SourceLocation kLoc{"scene.pbrt", 3, 7};

const std::string kAsciiHeader =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
const std::string kAsciiBody = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

void check(const std::string &text) { check_ply_element_counts(text, text.size(), "m.ply", kLoc); }

TEST(PlyHeader, ConsistentFilesPass) {
    EXPECT_NO_THROW(check(kAsciiHeader + kAsciiBody));
    // Binary: 3 vertices of 12 bytes and one face of at least 1 byte (an empty list) fit 37 bytes.
    std::string binary = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                         "property float y\nproperty float z\nelement face 1\n"
                         "property list uchar int vertex_indices\nend_header\n";
    EXPECT_NO_THROW(check(binary + std::string(37, '\0')));
    EXPECT_THROW(check(binary + std::string(36, '\0')), InputError);
}

TEST(PlyHeader, CountsBeyondTheFileAreErrorsAtTheLocation) {
    std::string lying = kAsciiHeader;
    lying.replace(lying.find("vertex 3"), 8, "vertex 2000000000");
    try {
        check(lying + kAsciiBody);
        ADD_FAILURE() << "no error";
    } catch (const InputError &e) {
        EXPECT_EQ(e.location().line, 3);
        EXPECT_EQ(e.location().column, 7);
        EXPECT_NE(e.message().find("2000000000 \"vertex\" elements"), std::string::npos) << e.message();
    }
    // The largest count a 64-bit number holds must not overflow the comparison.
    std::string huge = kAsciiHeader;
    huge.replace(huge.find("face 1"), 6, "face 18446744073709551615");
    EXPECT_THROW(check(huge + kAsciiBody), InputError);
}

TEST(PlyHeader, OtherTextIsLeftToTheMeshReader) {
    EXPECT_NO_THROW(check("o cube\nv 0 0 0\n"));                          // not PLY (an OBJ file)
    EXPECT_NO_THROW(check("ply\nformat ascii 1.0\nelement vertex 99"));  // header never ends
    EXPECT_NO_THROW(check("ply\nformat ascii 1.0\nelement vertex many\nend_header\n"));
}

} // namespace
} // namespace caustica
