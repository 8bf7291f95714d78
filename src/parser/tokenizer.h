// Splits pbrt scene text into tokens, each with the file, line and column where it starts.
//
// Tokens: quoted strings ("..." with the escapes \b \f \n \r \t \\ \' \"), the brackets [ and ],
// and words (directive names, numbers, true/false): runs of characters up to whitespace, a
// quote, a bracket or '#'. '#' starts a comment that runs to the end of the line.
#pragma once

#include "core/error.h"

#include <string>

namespace caustica {

struct Token {
    enum class Kind { Word, String, OpenBracket, CloseBracket, End };
    Kind kind = Kind::End;
    std::string text;  // string contents with escapes decoded; empty for brackets and End
    // Where the token starts (for End: just past the last character of the file). The file
    // name is owned by whoever owns the Tokenizer and outlives the token.
    const std::string *file = nullptr;
    int line = 1, column = 1;

    SourceLocation location() const { return {file ? *file : std::string(), line, column}; }
    // The token as written, for messages: quoted strings re-quoted, End as "end of file".
    std::string describe() const;
};

class Tokenizer {
  public:
    // `file_name` must outlive the tokenizer and its tokens.
    Tokenizer(std::string contents, const std::string *file_name);
    // The next token; Kind::End (repeatedly) at the end of the text. Throws InputError for
    // an unterminated string, an unknown escape or UTF-16 text.
    Token next();

  private:
    int peek(size_t ahead = 0) const;
    void advance();  // consumes one character, keeping line and column current

    std::string text_;
    const std::string *file_;
    size_t pos_ = 0;
    int line_ = 1, column_ = 1;
};

} // namespace caustica
