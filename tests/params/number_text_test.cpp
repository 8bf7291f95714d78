#include "params/number_text.h"

#include <gtest/gtest.h>

namespace caustica {
namespace {

NumberTextStatus status(const char *text) {
    double v;
    return parse_number_text(text, &v);
}

double value(const char *text) {
    double v = -12345;
    EXPECT_EQ(parse_number_text(text, &v), NumberTextStatus::Ok) << text;
    return v;
}

TEST(NumberText, AcceptsDecimalForms) {
    EXPECT_EQ(value("0"), 0);
    EXPECT_EQ(value("42"), 42);
    EXPECT_EQ(value("-7"), -7);
    EXPECT_EQ(value("+3"), 3);
    EXPECT_EQ(value(".5"), 0.5);
    EXPECT_EQ(value("-.25"), -0.25);
    EXPECT_EQ(value("1."), 1);
    EXPECT_EQ(value("2.5e-1"), 0.25);
    EXPECT_EQ(value("1E3"), 1000);
    // Underflow is harmless: the value is (close to) zero.
    EXPECT_LT(std::abs(value("1e-400")), 1e-300);
}

TEST(NumberText, RejectsNonNumbers) {
    for (const char *t : {"", "+", "-", "abc", "1x", "1e", "--1", "0x10", "1,5", ".", "e5", "true"})
        EXPECT_EQ(status(t), NumberTextStatus::NotANumber) << t;
}

TEST(NumberText, RejectsNonFiniteValues) {
    for (const char *t : {"nan", "NaN", "-nan", "inf", "-inf", "Infinity", "1e999", "-1e400"})
        EXPECT_EQ(status(t), NumberTextStatus::NotFinite) << t;
}

} // namespace
} // namespace caustica
