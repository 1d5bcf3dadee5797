// Malformed scenes: each must throw illum::Error naming file:line:column and saying what is wrong.
#include <gtest/gtest.h>

#include <cerrno>
#include <cstring>

#include "illum/scene/pbrt/parser.h"
#include "test_util.h"

namespace illum {
namespace {

using test::expect_error;

void parse_bad(const std::string& text) { parse_pbrt_string(text, "bad.pbrt", "/nowhere"); }

struct Case {
    const char* what;
    const char* text;
    const char* where;
    const char* phrase;
};

const Case kCases[] = {
    {"unterminated string", "WorldBegin\nShape \"sphere\" \"float radius [ 1 ]\n", "bad.pbrt:2:16",
     "unterminated string"},
    {"bad escape", "WorldBegin\nShape \"sph\\ere\"", "bad.pbrt:2:11", "bad escape sequence '\\e'"},
    {"stray character", "WorldBegin\nShape \"sphere\" @", "bad.pbrt:2:16", "unexpected character '@'"},
    {"unknown directive", "WorldBegin\n  Foo \"bar\"\n", "bad.pbrt:2:3", "unknown directive \"Foo\""},
    {"unknown parameter type", "WorldBegin\nShape \"sphere\" \"flaot radius\" 1", "bad.pbrt:2:16",
     "unknown parameter type \"flaot\""},
    {"declaration without a name", "WorldBegin\nShape \"sphere\" \"float\" 1", "bad.pbrt:2:16",
     "bad parameter declaration"},
    {"string where numbers are expected", "WorldBegin\nShape \"sphere\" \"float radius\" [ \"one\" ]",
     "bad.pbrt:2:33", "expects numbers, found string"},
    {"number where strings are expected", "WorldBegin\nShape \"plymesh\" \"string filename\" 3",
     "bad.pbrt:2:35", "expects quoted strings, found number"},
    {"bool that is not true or false", "Film \"rgb\" \"bool savefp16\" \"yes\"", "bad.pbrt:1:28",
     "\"yes\" is not true or false"},
    {"bare word as a value", "Film \"rgb\" \"bool savefp16\" maybe", "bad.pbrt:1:28", "missing value"},
    {"integer with a fraction", "Sampler \"halton\" \"integer pixelsamples\" 1.5", "bad.pbrt:1:18",
     "not an integer"},
    {"rgb with two values", "WorldBegin\nMaterial \"diffuse\" \"rgb reflectance\" [ 1 2 ]", "bad.pbrt:2:20",
     "multiple of 3"},
    {"blackbody with two values", "WorldBegin\nLightSource \"point\" \"blackbody I\" [ 3000 1 ]",
     "bad.pbrt:2:21", "blackbody needs 1 value"},
    {"missing ]", "WorldBegin\nShape \"sphere\" \"float radius\" [ 1\nShape \"sphere\"", "bad.pbrt:3:1",
     "missing ']'"},
    {"unterminated [", "WorldBegin\nShape \"sphere\" \"float radius\" [ 1 2", "bad.pbrt:2:31",
     "unterminated '['"},
    {"Translate with 2 numbers", "Translate 1 2\nWorldBegin", "bad.pbrt:1:1",
     "Translate expects 3 numbers, found 2"},
    {"Rotate with 3 numbers", "WorldBegin\n Rotate 90 0 1", "bad.pbrt:2:2", "Rotate expects 4 numbers"},
    {"Transform with 15 numbers", "Transform [ 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 ]", "bad.pbrt:1:1",
     "Transform expects 16 numbers, found 15"},
    {"singular Transform", "Transform [ 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 1 ]", "bad.pbrt:1:1", "singular"},
    {"NaN in a transform", "Translate 1 nan 0", "bad.pbrt:1:13", "not a finite number"},
    {"Inf in a transform", "WorldBegin\nScale 1 1 1e999", "bad.pbrt:2:11", "not a finite number"},
    {"Scale by zero", "Scale 1 0 1", "bad.pbrt:1:1", "Scale by zero"},
    {"zero rotation axis", "Rotate 30 0 0 0", "bad.pbrt:1:1", "axis"},
    {"LookAt with coincident points", "LookAt 1 1 1 1 1 1 0 1 0", "bad.pbrt:1:1", "LookAt"},
    {"number where a directive is expected", "WorldBegin\nTranslate 1 2 3 4", "bad.pbrt:2:17",
     "expected a directive, found number"},
    {"AttributeEnd without AttributeBegin", "WorldBegin\nAttributeBegin\nAttributeEnd\n  AttributeEnd",
     "bad.pbrt:4:3", "AttributeEnd without matching AttributeBegin"},
    {"missing AttributeEnd", "WorldBegin\nAttributeBegin\n AttributeBegin\n AttributeEnd\n", "bad.pbrt:2:1",
     "AttributeBegin without matching AttributeEnd"},
    {"TransformEnd closing an AttributeBegin", "WorldBegin\nAttributeBegin\nTransformEnd", "bad.pbrt:3:1",
     "does not match the AttributeBegin at bad.pbrt:2:1"},
    {"WorldBegin twice", "WorldBegin\nWorldBegin", "bad.pbrt:2:1", "WorldBegin appears twice"},
    {"Shape before WorldBegin", "Shape \"sphere\"", "bad.pbrt:1:1", "only allowed after WorldBegin"},
    {"TransformTimes ending before they start", "TransformTimes 1 0.5\nWorldBegin", "bad.pbrt:1:1",
     "TransformTimes: the end time 0.5 is before the start time 1"},
    {"TransformTimes in the world", "WorldBegin\nTransformTimes 0 1", "bad.pbrt:2:1",
     "only allowed before WorldBegin"},
    {"ActiveTransform with a bad keyword", "ActiveTransform Sometimes\nWorldBegin", "bad.pbrt:1:17",
     "ActiveTransform expects All, StartTime or EndTime, found Sometimes"},
    {"a moving projective transform",
     "ActiveTransform EndTime\nTransform [1 0 0 0 0 1 0 0 0 0 1 1 0 0 0 1]\n"
     "ActiveTransform All\nCamera \"perspective\"\nWorldBegin",
     "bad.pbrt:4:1", "a moving transform must be affine"},
    {"Camera after WorldBegin", "WorldBegin\nCamera \"perspective\"", "bad.pbrt:2:1",
     "only allowed before WorldBegin"},
    {"Film after WorldBegin", "WorldBegin\nFilm \"rgb\"", "bad.pbrt:2:1", "only allowed before WorldBegin"},
    {"unknown named material", "WorldBegin\nNamedMaterial \"Gold\"\nShape \"sphere\"", "bad.pbrt:2:1",
     "NamedMaterial \"Gold\": no material of that name"},
    {"unknown object", "WorldBegin\n ObjectInstance \"tree\"", "bad.pbrt:2:2",
     "ObjectInstance \"tree\": no object of that name"},
    {"nested ObjectBegin", "WorldBegin\nObjectBegin \"a\"\nObjectBegin \"b\"", "bad.pbrt:3:1",
     "object definitions cannot nest"},
    {"ObjectEnd without ObjectBegin", "WorldBegin\nObjectEnd", "bad.pbrt:2:1",
     "ObjectEnd without matching ObjectBegin"},
    {"missing ObjectEnd", "WorldBegin\nObjectBegin \"a\"", "bad.pbrt:2:1",
     "ObjectBegin without matching ObjectEnd"},
    {"named material redefined",
     "WorldBegin\nMakeNamedMaterial \"m\" \"string type\" \"diffuse\"\nMakeNamedMaterial \"m\" \"string "
     "type\" "
     "\"diffuse\"",
     "bad.pbrt:3:19", "redefined (first defined at bad.pbrt:2:1)"},
    {"MakeNamedMaterial without type", "WorldBegin\nMakeNamedMaterial \"m\" \"rgb reflectance\" [ 1 1 1 ]",
     "bad.pbrt:2:1", "missing parameter \"string type\""},
    {"texture of an unknown value type", "WorldBegin\nTexture \"t\" \"color\" \"checkerboard\"",
     "bad.pbrt:2:13", "unknown texture value type \"color\""},
    {"directive name expected but string found", "\"float fov\" 3", "bad.pbrt:1:1", "expected a directive"},
    {"Camera without a type", "Camera\nWorldBegin", "bad.pbrt:2:1", "Camera expects a quoted camera type"},
    {"unknown Attribute target", "WorldBegin\nAttribute \"camera\" \"float x\" 1", "bad.pbrt:2:1",
     "unknown target \"camera\""},
    {"missing Include file", "WorldBegin\nInclude \"does-not-exist.pbrt\"", "bad.pbrt:2:9",
     "cannot open included file \"does-not-exist.pbrt\" (/nowhere/does-not-exist.pbrt): No such file or "
     "directory"},
    {"LightSource inside an object", "WorldBegin\nObjectBegin \"a\"\nLightSource \"point\"", "bad.pbrt:3:1",
     "lights cannot be instanced"},
    // pbrt-v4 stops with this message too; the position is the end of the file.
    {"empty file", "", "bad.pbrt:1:1", "End of files before WorldBegin"},
    {"comments only", "# nothing here\n\n", "bad.pbrt:3:1", "End of files before WorldBegin"},
    {"options without a world", "Camera \"perspective\"\nFilm \"rgb\" ", "bad.pbrt:2:12",
     "End of files before WorldBegin"},
};

TEST(PbrtParserErrors, MalformedInputCorpus) {
    for (const Case& c : kCases) {
        SCOPED_TRACE(c.what);
        expect_error([&] { parse_bad(c.text); }, c.where, c.phrase);
    }
}

TEST(PbrtParserErrors, ErrorCarriesStructuredLocation) {
    try {
        parse_bad("WorldBegin\n\n   Bogus");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.where().file, "bad.pbrt");
        EXPECT_EQ(e.where().line, 3);
        EXPECT_EQ(e.where().column, 4);
        EXPECT_EQ(e.message(), "unknown directive \"Bogus\"");
        EXPECT_EQ(std::string(e.what()), "bad.pbrt:3:4: unknown directive \"Bogus\"");
    }
}

TEST(PbrtParserErrors, IncludeCycleIsReportedWithItsChain) {
    test::TempDir dir("cycle");
    std::string a = dir.write("a.pbrt", "WorldBegin\nInclude \"b.pbrt\"\n");
    std::string b = dir.write("b.pbrt", "Shape \"sphere\"\n  Include \"a.pbrt\"\n");
    expect_error([&] { parse_pbrt_file(a); }, b + ":2:11", "include cycle: " + a + " -> " + b + " -> " + a);
}

TEST(PbrtParserErrors, SelfInclude) {
    test::TempDir dir("self");
    std::string a = dir.write("a.pbrt", "Include \"a.pbrt\"\n");
    expect_error([&] { parse_pbrt_file(a); }, a + ":1:9", "include cycle");
}

TEST(PbrtParserErrors, ErrorInsideIncludedFileNamesThatFile) {
    test::TempDir dir("inner");
    std::string inner = dir.write("inner.pbrt", "\n\n    Translate 1 2\n");
    expect_error(
        [&] { parse_pbrt_string("WorldBegin Include \"inner.pbrt\" Shape \"x\"", "main.pbrt", dir.path()); },
        inner + ":3:5", "Translate expects 3 numbers");
}

TEST(PbrtParserErrors, IncludingADirectoryIsAnError) {
    test::TempDir dir("incdir");
    dir.write("sub/x.pbrt", "");
    expect_error([&] { parse_pbrt_string("Include \"sub\"", "main.pbrt", dir.path()); }, "main.pbrt:1:9",
                 std::string("cannot open included file \"sub\" (") + dir.file("sub") +
                     "): " + std::strerror(EISDIR));
}

// The world may begin in an included file, and an included fragment needs no WorldBegin of its own; but the
// end of the main file is checked even when an included file ends first.
TEST(PbrtParserErrors, WorldBeginMayComeFromAnIncludedFile) {
    test::TempDir dir("worldinc");
    dir.write("world.pbrt", "WorldBegin\n");
    dir.write("shapes.pbrt", "Shape \"sphere\"\n");
    dir.write("camera.pbrt", "Camera \"perspective\"\n");
    SceneDesc s =
        parse_pbrt_string("Include \"world.pbrt\"\nInclude \"shapes.pbrt\"\n", "main.pbrt", dir.path());
    EXPECT_EQ(s.shapes.size(), 1u);
    expect_error([&] { parse_pbrt_string("Include \"camera.pbrt\"\n", "main.pbrt", dir.path()); },
                 "main.pbrt:2:1", "End of files before WorldBegin");
}

// --strict: the first of the parser's warnings is an error at its position; without it, a warning.
TEST(PbrtParserErrors, StrictTurnsParserWarningsIntoErrors) {
    const char* cases[][3] = {
        {"WorldBegin\nActiveTransform EndTime\nTranslate 1 0 0\nLightSource \"point\"\n", "bad.pbrt:4:1",
         "a moving light is not supported"},
        {"WorldBegin\nTransformBegin\nTransformEnd\n", "bad.pbrt:2:1", "TransformBegin/TransformEnd"},
        {"WorldBegin\nWorldEnd\n", "bad.pbrt:2:1", "WorldEnd"},
    };
    ParseOptions strict;
    strict.strict = true;
    for (auto& c : cases) {
        SCOPED_TRACE(c[0]);
        SceneDesc s = parse_pbrt_string(c[0], "bad.pbrt", "/nowhere");
        ASSERT_EQ(s.warnings.size(), 1u);
        EXPECT_NE(s.warnings[0].find(std::string(c[1]) + ": " + c[2]), std::string::npos) << s.warnings[0];
        expect_error([&] { parse_pbrt_string(c[0], "bad.pbrt", "/nowhere", strict); }, c[1],
                     std::string(c[2]));
    }
}

TEST(PbrtParserErrors, MissingTopLevelFile) {
    expect_error([] { parse_pbrt_file("/nonexistent/scene.pbrt"); }, "/nonexistent/scene.pbrt",
                 std::string("cannot open scene file: ") + std::strerror(ENOENT));
}

} // namespace
} // namespace illum
