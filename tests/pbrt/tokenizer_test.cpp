#include "illum/scene/pbrt/tokenizer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "test_util.h"

namespace illum {
namespace {

// A token with its raw text copied out (Token::text points into the tokenizer's buffer).
struct OwnedToken : Token {
    std::string raw;
};

std::vector<OwnedToken> all_tokens(const std::string& text) {
    Tokenizer tk(text, "t.pbrt");
    std::vector<OwnedToken> r;
    while (true) {
        Token t = tk.next();
        if (t.kind == TokenKind::End) break;
        OwnedToken o;
        static_cast<Token&>(o) = std::move(t);
        o.raw = std::string(o.text);
        o.text = {};
        r.push_back(std::move(o));
    }
    return r;
}

TEST(Tokenizer, KindsValuesAndPositions) {
    auto t =
        all_tokens("Shape \"sphere\" # comment \"not a string\"\n  \"float radius\" [ 1.5 -2 +3e2 .5 ]\n");
    ASSERT_EQ(t.size(), 9u);
    EXPECT_EQ(t[0].kind, TokenKind::Word);
    EXPECT_EQ(t[0].raw, "Shape");
    EXPECT_EQ(t[0].line, 1);
    EXPECT_EQ(t[0].column, 1);
    EXPECT_EQ(t[1].kind, TokenKind::String);
    EXPECT_EQ(t[1].str, "sphere");
    EXPECT_EQ(t[1].column, 7);
    EXPECT_EQ(t[2].kind, TokenKind::String);
    EXPECT_EQ(t[2].str, "float radius");
    EXPECT_EQ(t[2].line, 2);
    EXPECT_EQ(t[2].column, 3);
    EXPECT_EQ(t[3].kind, TokenKind::LBracket);
    EXPECT_EQ(t[3].column, 18);
    EXPECT_EQ(t[4].kind, TokenKind::Number);
    EXPECT_DOUBLE_EQ(t[4].number, 1.5);
    EXPECT_DOUBLE_EQ(t[5].number, -2);
    EXPECT_DOUBLE_EQ(t[6].number, 300);
    EXPECT_DOUBLE_EQ(t[7].number, 0.5);
    EXPECT_EQ(t[8].kind, TokenKind::RBracket);
}

TEST(Tokenizer, Escapes) {
    auto t = all_tokens(R"("a\nb\tc\\d\"e")");
    ASSERT_EQ(t.size(), 1u);
    EXPECT_EQ(t[0].str, "a\nb\tc\\d\"e");
}

TEST(Tokenizer, BracketsNeedNoSpaces) {
    auto t = all_tokens("[1 2]\"x\"[\"y\"]");
    ASSERT_EQ(t.size(), 8u);
    EXPECT_EQ(t[0].kind, TokenKind::LBracket);
    EXPECT_EQ(t[2].kind, TokenKind::Number);
    EXPECT_EQ(t[3].kind, TokenKind::RBracket);
    EXPECT_EQ(t[4].str, "x");
    EXPECT_EQ(t[5].kind, TokenKind::LBracket);
    EXPECT_EQ(t[6].str, "y");
    EXPECT_EQ(t[7].kind, TokenKind::RBracket);
}

TEST(Tokenizer, NanAndInfAreNumbers) {
    auto t = all_tokens("nan inf -inf 1e999");
    ASSERT_EQ(t.size(), 4u);
    EXPECT_TRUE(std::isnan(t[0].number));
    EXPECT_TRUE(std::isinf(t[1].number));
    EXPECT_TRUE(std::isinf(t[2].number) && t[2].number < 0);
    EXPECT_TRUE(std::isinf(t[3].number));
}

TEST(Tokenizer, ByteOrderMarkIsSkipped) {
    auto t = all_tokens("\xEF\xBB\xBFWorldBegin");
    ASSERT_EQ(t.size(), 1u);
    EXPECT_EQ(t[0].raw, "WorldBegin");
}

TEST(Tokenizer, PeekDoesNotConsume) {
    Tokenizer tk("A B", "t.pbrt");
    EXPECT_EQ(tk.peek().text, "A");
    EXPECT_EQ(tk.peek().text, "A");
    EXPECT_EQ(tk.next().text, "A");
    EXPECT_EQ(tk.next().text, "B");
    EXPECT_EQ(tk.next().kind, TokenKind::End);
    EXPECT_EQ(tk.next().kind, TokenKind::End);
}

TEST(Tokenizer, Errors) {
    using test::expect_error;
    expect_error([] { all_tokens("Shape \"sphere\n"); }, "t.pbrt:1:7", "unterminated string");
    expect_error([] { all_tokens("Shape \"sph"); }, "t.pbrt:1:7", "unterminated string");
    expect_error([] { all_tokens("\n  \"a\\qb\""); }, "t.pbrt:2:5", "bad escape");
    expect_error([] { all_tokens("WorldBegin\n Shape { }"); }, "t.pbrt:2:8", "unexpected character '{'");
    expect_error([] { all_tokens("x \x01"); }, "t.pbrt:1:3", "unexpected character '\\x01'");
    expect_error([] { all_tokens("Translate 1.2.3 0 0"); }, "t.pbrt:1:11", "malformed number \"1.2.3\"");
    expect_error([] { all_tokens("Translate 1abc 0 0"); }, "t.pbrt:1:11", "malformed number");
}

} // namespace
} // namespace illum
