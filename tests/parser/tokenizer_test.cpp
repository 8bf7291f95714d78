#include "parser/tokenizer.h"

#include <gtest/gtest.h>

#include <vector>

namespace caustica {
namespace {

const std::string kFile = "t.pbrt";

std::vector<Token> tokenize(const std::string &text) {
    Tokenizer t(text, &kFile);
    std::vector<Token> tokens;
    while (true) {
        Token tok = t.next();
        if (tok.kind == Token::Kind::End) break;
        tokens.push_back(tok);
    }
    return tokens;
}

SourceLocation error_location(const std::string &text) {
    try {
        tokenize(text);
    } catch (const InputError &e) {
        return e.location();
    }
    ADD_FAILURE() << "no error for: " << text;
    return {};
}

TEST(Tokenizer, KindsTextAndLocations) {
    auto tokens = tokenize("Shape \"sphere\"\n  \"float radius\" [ 2.5 ]");
    ASSERT_EQ(tokens.size(), 6u);
    EXPECT_EQ(tokens[0].kind, Token::Kind::Word);
    EXPECT_EQ(tokens[0].text, "Shape");
    EXPECT_EQ(tokens[1].kind, Token::Kind::String);
    EXPECT_EQ(tokens[1].text, "sphere");
    EXPECT_EQ(tokens[1].line, 1);
    EXPECT_EQ(tokens[1].column, 7);
    EXPECT_EQ(tokens[2].text, "float radius");
    EXPECT_EQ(tokens[2].line, 2);
    EXPECT_EQ(tokens[2].column, 3);
    EXPECT_EQ(tokens[3].kind, Token::Kind::OpenBracket);
    EXPECT_EQ(tokens[3].column, 18);
    EXPECT_EQ(tokens[4].text, "2.5");
    EXPECT_EQ(tokens[5].kind, Token::Kind::CloseBracket);
    EXPECT_EQ(tokens[5].location().to_string(), "t.pbrt:2:24");
}

TEST(Tokenizer, BracketsAndQuotesEndWords) {
    auto tokens = tokenize("[1 2]\"a\"b#c\nd");
    ASSERT_EQ(tokens.size(), 7u);
    EXPECT_EQ(tokens[0].kind, Token::Kind::OpenBracket);
    EXPECT_EQ(tokens[1].text, "1");
    EXPECT_EQ(tokens[2].text, "2");
    EXPECT_EQ(tokens[3].kind, Token::Kind::CloseBracket);
    EXPECT_EQ(tokens[4].text, "a");
    EXPECT_EQ(tokens[5].text, "b");
    EXPECT_EQ(tokens[6].text, "d");
    EXPECT_EQ(tokens[6].line, 2);
}

TEST(Tokenizer, CommentsRunToEndOfLine) {
    auto tokens = tokenize("# a \"comment\" [ with tokens\nWorldBegin # trailing\n#last");
    ASSERT_EQ(tokens.size(), 1u);
    EXPECT_EQ(tokens[0].text, "WorldBegin");
    EXPECT_EQ(tokens[0].line, 2);
    EXPECT_EQ(tokens[0].column, 1);
}

TEST(Tokenizer, Escapes) {
    auto tokens = tokenize(R"("a\"b\\c\n\t\'")");
    ASSERT_EQ(tokens.size(), 1u);
    EXPECT_EQ(tokens[0].text, "a\"b\\c\n\t'");
}

TEST(Tokenizer, LineEndingsAndCharacterColumns) {
    // CRLF and lone CR both end lines; a two-byte UTF-8 character is one column.
    auto tokens = tokenize("a\r\nb\rc \"\xC3\xA9\" d");
    ASSERT_EQ(tokens.size(), 5u);
    EXPECT_EQ(tokens[1].line, 2);
    EXPECT_EQ(tokens[2].line, 3);
    EXPECT_EQ(tokens[2].column, 1);
    EXPECT_EQ(tokens[4].text, "d");
    EXPECT_EQ(tokens[4].column, 7);
}

TEST(Tokenizer, Utf8ByteOrderMarkIsSkipped) {
    auto tokens = tokenize("\xEF\xBB\xBFWorldBegin");
    ASSERT_EQ(tokens.size(), 1u);
    EXPECT_EQ(tokens[0].text, "WorldBegin");
    EXPECT_EQ(tokens[0].column, 1);
}

TEST(Tokenizer, EndTokenIsPastTheLastCharacter) {
    Tokenizer t("ab\ncd", &kFile);
    t.next();
    t.next();
    Token end = t.next();
    EXPECT_EQ(end.kind, Token::Kind::End);
    EXPECT_EQ(end.line, 2);
    EXPECT_EQ(end.column, 3);
    EXPECT_EQ(t.next().kind, Token::Kind::End);
}

TEST(Tokenizer, ErrorsPointAtTheString) {
    SourceLocation loc = error_location("Shape\n  \"sphere");
    EXPECT_EQ(loc.line, 2);
    EXPECT_EQ(loc.column, 3);
    loc = error_location("\"ab\ncd\"");
    EXPECT_EQ(loc.line, 1);
    EXPECT_EQ(loc.column, 1);
    // An unknown escape is reported at its backslash.
    loc = error_location("  \"a\\qb\"");
    EXPECT_EQ(loc.column, 5);
    loc = error_location("\xFF\xFE\x00\x00");
    EXPECT_EQ(loc.line, 1);
}

} // namespace
} // namespace caustica
