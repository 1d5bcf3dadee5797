#include "illum/scene/pbrt/tokenizer.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>

namespace illum {

const char* to_string(TokenKind k) {
    switch (k) {
    case TokenKind::Word:
        return "word";
    case TokenKind::String:
        return "string";
    case TokenKind::Number:
        return "number";
    case TokenKind::LBracket:
        return "'['";
    case TokenKind::RBracket:
        return "']'";
    case TokenKind::End:
        return "end of file";
    }
    return "?";
}

Tokenizer::Tokenizer(std::string text, std::string filename)
    : text_(std::move(text)), filename_(std::move(filename)) {
    // A UTF-8 byte order mark is skipped (columns still count from the start of the line).
    if (text_.compare(0, 3, "\xEF\xBB\xBF") == 0) pos_ = 3;
}

void Tokenizer::fail(const Token& t, const std::string& message) const { fail_at(t.line, t.column, message); }

void Tokenizer::fail_at(int line, int column, const std::string& message) const {
    throw Error(SourceLocation{filename_, line, column}, message);
}

const Token& Tokenizer::peek() {
    if (!has_lookahead_) {
        lookahead_ = scan();
        has_lookahead_ = true;
    }
    return lookahead_;
}

Token Tokenizer::next() {
    if (has_lookahead_) {
        has_lookahead_ = false;
        return std::move(lookahead_);
    }
    return scan();
}

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
bool is_delimiter(char c) { return is_space(c) || c == '"' || c == '[' || c == ']' || c == '#'; }
bool is_word_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_word_char(char c) { return is_word_start(c) || (c >= '0' && c <= '9') || c == '-' || c == '.'; }
bool is_number_start(char c) { return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.'; }

std::string printable(char c) {
    unsigned char u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7f) return std::string(1, c);
    return fmt::format("\\x{:02x}", u);
}

bool iequals(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        char x = a[i], y = b[i];
        if (x >= 'A' && x <= 'Z') x = char(x - 'A' + 'a');
        if (x != y) return false;
    }
    return true;
}

// Parses a whole token as a number; false when it is not one.
bool parse_number(std::string_view s, double& out) {
    if (!s.empty() && s[0] == '+') s.remove_prefix(1);
    if (s.empty() || s[0] == '+' || (s[0] == '-' && s.size() > 1 && s[1] == '+')) return false;
    const char* end = s.data() + s.size();
    auto [ptr, ec] = std::from_chars(s.data(), end, out);
    if (ptr != end) return false;
    if (ec == std::errc::result_out_of_range) {
        // Overflow to +-inf, underflow to 0 or a denormal, as strtod does.
        std::string copy(s);
        out = std::strtod(copy.c_str(), nullptr);
        return true;
    }
    return ec == std::errc();
}

} // namespace

Token Tokenizer::scan() {
    const size_t n = text_.size();
    // Skip whitespace and comments.
    while (pos_ < n) {
        char c = text_[pos_];
        if (c == '\n') {
            ++pos_;
            ++line_;
            line_start_ = pos_;
        } else if (is_space(c)) {
            ++pos_;
        } else if (c == '#') {
            while (pos_ < n && text_[pos_] != '\n') ++pos_;
        } else {
            break;
        }
    }
    Token t;
    t.line = line_;
    t.column = int(pos_ - line_start_) + 1;
    if (pos_ >= n) {
        t.kind = TokenKind::End;
        return t;
    }
    const size_t start = pos_;
    const char c = text_[pos_];
    if (c == '[' || c == ']') {
        t.kind = c == '[' ? TokenKind::LBracket : TokenKind::RBracket;
        ++pos_;
        t.text = std::string_view(text_).substr(start, 1);
        return t;
    }
    if (c == '"') {
        t.kind = TokenKind::String;
        ++pos_;
        while (true) {
            if (pos_ >= n || text_[pos_] == '\n')
                fail_at(t.line, t.column, "unterminated string (missing closing '\"')");
            char d = text_[pos_];
            if (d == '"') {
                ++pos_;
                break;
            }
            if (d == '\\') {
                if (pos_ + 1 >= n) fail_at(t.line, t.column, "unterminated string (missing closing '\"')");
                char e = text_[pos_ + 1];
                switch (e) {
                case 'n':
                    t.str += '\n';
                    break;
                case 't':
                    t.str += '\t';
                    break;
                case '\\':
                    t.str += '\\';
                    break;
                case '"':
                    t.str += '"';
                    break;
                default:
                    fail_at(line_, int(pos_ - line_start_) + 1,
                            fmt::format("bad escape sequence '\\{}' in string", printable(e)));
                }
                pos_ += 2;
                continue;
            }
            t.str += d;
            ++pos_;
        }
        t.text = std::string_view(text_).substr(start, pos_ - start);
        return t;
    }
    if (is_word_start(c)) {
        while (pos_ < n && is_word_char(text_[pos_])) ++pos_;
        t.text = std::string_view(text_).substr(start, pos_ - start);
        if (iequals(t.text, "nan") || iequals(t.text, "inf") || iequals(t.text, "infinity")) {
            t.kind = TokenKind::Number;
            t.number = iequals(t.text, "nan") ? std::nan("") : HUGE_VAL;
        } else {
            t.kind = TokenKind::Word;
        }
        return t;
    }
    if (is_number_start(c)) {
        while (pos_ < n && !is_delimiter(text_[pos_])) ++pos_;
        t.text = std::string_view(text_).substr(start, pos_ - start);
        t.kind = TokenKind::Number;
        if (!parse_number(t.text, t.number))
            fail_at(t.line, t.column,
                    fmt::format("malformed number \"{}\"", t.text.size() > 40
                                                               ? std::string(t.text.substr(0, 40)) + "..."
                                                               : std::string(t.text)));
        return t;
    }
    fail_at(t.line, t.column, fmt::format("unexpected character '{}'", printable(c)));
}

} // namespace illum
