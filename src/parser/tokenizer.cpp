#include "parser/tokenizer.h"

namespace caustica {

std::string Token::describe() const {
    switch (kind) {
    case Kind::Word: return "'" + text + "'";
    case Kind::String: return "\"" + text + "\"";
    case Kind::OpenBracket: return "'['";
    case Kind::CloseBracket: return "']'";
    case Kind::End: return "end of file";
    }
    return {};
}

Tokenizer::Tokenizer(std::string contents, const std::string *file_name)
    : text_(std::move(contents)), file_(file_name) {
    auto byte = [&](size_t i) { return i < text_.size() ? (unsigned char)text_[i] : 0u; };
    if ((byte(0) == 0xFE && byte(1) == 0xFF) || (byte(0) == 0xFF && byte(1) == 0xFE))
        throw InputError({*file_, 1, 1}, "the file is UTF-16 encoded; scene files must be UTF-8");
    // A UTF-8 byte order mark carries no meaning; skip it without counting a column.
    if (byte(0) == 0xEF && byte(1) == 0xBB && byte(2) == 0xBF) pos_ = 3;
}

int Tokenizer::peek(size_t ahead) const {
    size_t i = pos_ + ahead;
    return i < text_.size() ? (unsigned char)text_[i] : -1;
}

void Tokenizer::advance() {
    char c = text_[pos_++];
    // "\n", "\r\n" and a lone "\r" each end a line.
    if (c == '\n' || (c == '\r' && peek() != '\n')) {
        ++line_;
        column_ = 1;
    } else if (c != '\r' && (static_cast<unsigned char>(c) & 0xC0) != 0x80) {
        // Columns count characters: UTF-8 continuation bytes do not start a new one.
        ++column_;
    }
}

Token Tokenizer::next() {
    while (true) {
        int c = peek();
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v') {
            advance();
        } else if (c == '#') {
            while (peek() != -1 && peek() != '\n' && peek() != '\r') advance();
        } else {
            break;
        }
    }
    Token tok;
    tok.file = file_;
    tok.line = line_;
    tok.column = column_;
    int c = peek();
    if (c == -1) return tok;
    if (c == '[' || c == ']') {
        tok.kind = c == '[' ? Token::Kind::OpenBracket : Token::Kind::CloseBracket;
        advance();
        return tok;
    }
    if (c == '"') {
        tok.kind = Token::Kind::String;
        advance();
        while (true) {
            int ch = peek();
            if (ch == -1 || ch == '\n' || ch == '\r')
                throw InputError(tok.location(), "unterminated string (no closing '\"' on this line)");
            if (ch == '"') {
                advance();
                return tok;
            }
            if (ch == '\\') {
                SourceLocation escape_loc{*file_, line_, column_};
                advance();
                int e = peek();
                char decoded;
                switch (e) {
                case 'b': decoded = '\b'; break;
                case 'f': decoded = '\f'; break;
                case 'n': decoded = '\n'; break;
                case 'r': decoded = '\r'; break;
                case 't': decoded = '\t'; break;
                case '\\': decoded = '\\'; break;
                case '\'': decoded = '\''; break;
                case '"': decoded = '"'; break;
                case -1:
                case '\n':
                case '\r':
                    throw InputError(tok.location(), "unterminated string (ends in '\\')");
                default:
                    throw InputError(escape_loc, std::string("unknown escape sequence '\\") +
                                                     char(e) + "' in string");
                }
                tok.text.push_back(decoded);
                advance();
                continue;
            }
            tok.text.push_back(char(ch));
            advance();
        }
    }
    tok.kind = Token::Kind::Word;
    while (true) {
        int ch = peek();
        if (ch == -1 || ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r' || ch == '\f' ||
            ch == '\v' || ch == '"' || ch == '[' || ch == ']' || ch == '#')
            break;
        tok.text.push_back(char(ch));
        advance();
    }
    return tok;
}

} // namespace caustica
