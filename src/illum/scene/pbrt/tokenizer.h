// Tokenizer for the pbrt-v4 scene format, over one file's text held in memory. Tokens are bare words
// (directive names, true/false), quoted strings (escapes \n \t \\ \"), numbers and the brackets [ ];
// '#' starts a comment that runs to the end of the line. Each token carries its 1-based line and column
// (in bytes) so every error can name file:line:column.
#pragma once

#include <string>
#include <string_view>

#include "illum/util/error.h"

namespace illum {

enum class TokenKind { Word, String, Number, LBracket, RBracket, End };

struct Token {
    TokenKind kind = TokenKind::End;
    std::string_view text; // raw source text (a string with its quotes); valid while the Tokenizer lives
    std::string str;       // String: the value with escapes resolved
    double number = 0;     // Number: the value (also for the words nan, inf, infinity)
    int line = 0, column = 0;
};

const char* to_string(TokenKind k);

class Tokenizer {
public:
    // `filename` is only used in error positions.
    Tokenizer(std::string text, std::string filename);

    // The next token, consuming it; TokenKind::End at the end of the text (repeatedly).
    Token next();
    // The next token without consuming it.
    const Token& peek();

    const std::string& filename() const { return filename_; }
    SourceLocation location(const Token& t) const { return {filename_, t.line, t.column}; }
    [[noreturn]] void fail(const Token& t, const std::string& message) const;

private:
    Token scan();
    [[noreturn]] void fail_at(int line, int column, const std::string& message) const;

    std::string text_, filename_;
    size_t pos_ = 0;
    int line_ = 1;
    size_t line_start_ = 0; // offset of the first byte of the current line
    Token lookahead_;
    bool has_lookahead_ = false;
};

} // namespace illum
