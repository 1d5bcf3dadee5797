#include "illum/image/image_io.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "illum/image/file_bytes.h"
#include "illum/util/error.h"
#include "image/test_util.h"

namespace illum {
namespace {

using test::ScratchDir;
namespace fs = std::filesystem;

std::string error_of(auto&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(ImageIo, Extensions) {
    EXPECT_EQ(image_extension("a/b.c/out.EXR"), ".exr");
    EXPECT_EQ(image_extension("a/b.c/out"), "");
    EXPECT_EQ(image_extension(".png"), "");
    EXPECT_EQ(image_extension("dir/.png"), "");
    for (const char* ok : {"x.exr", "x.pfm", "x.hdr", "x.png", "DIR/X.PNG", "a.b.Exr"})
        EXPECT_TRUE(is_supported_output_extension(ok)) << ok;
    for (const char* bad : {"x.jpg", "x.tga", "x", "x.exr.tmp", "x.xyz", "exr", "x.pngx"})
        EXPECT_FALSE(is_supported_output_extension(bad)) << bad;
    for (const char* ok : {"x.jpg", "x.JPEG", "x.tga", "x.bmp", "x.exr", "x.hdr"})
        EXPECT_TRUE(is_supported_input_extension(ok)) << ok;
    EXPECT_FALSE(is_supported_input_extension("x.gif"));
}

TEST(ImageIo, ErrorMessagesNameTheFile) {
    ScratchDir dir;
    const Image img(2, 2, Color3(1.0f));
    EXPECT_EQ(error_of([&] { write_image(img, dir.file("x.xyz")); }),
              "unknown image extension \".xyz\" (use .exr, .pfm, .hdr or .png)");
    EXPECT_EQ(error_of([&] { write_image(img, dir.file("noext")); }),
              "\"" + dir.file("noext") + "\" has no image extension (use .exr, .pfm, .hdr or .png)");
    EXPECT_EQ(error_of([&] { read_image(dir.file("missing.exr")); }),
              "cannot read \"" + dir.file("missing.exr") + "\": No such file or directory");
    EXPECT_EQ(error_of([&] { write_image(img, "/nonexistent/dir/x.png"); }),
              "cannot write \"/nonexistent/dir/x.png\": No such file or directory");
    fs::create_directory(dir.file("d.exr"));
    EXPECT_EQ(error_of([&] { read_image(dir.file("d.exr")); }),
              "cannot read \"" + dir.file("d.exr") + "\": Is a directory");
    EXPECT_EQ(error_of([&] { read_image(dir.file("x.gif")); }).rfind("unknown image extension \".gif\"", 0),
              0u);
}

TEST(ImageIo, WriteToMissingFolderLeavesNothing) {
    ASSERT_FALSE(fs::exists("/nonexistent"));
    EXPECT_THROW(write_image(Image(2, 2), "/nonexistent/dir/x.exr"), Error);
    EXPECT_FALSE(fs::exists("/nonexistent"));
}

TEST(ImageIo, SuccessfulWriteReplacesAndLeavesNoTemporary) {
    ScratchDir dir;
    const std::string path = dir.file("out.pfm");
    write_image(Image(2, 1, Color3(1.0f)), path);
    write_image(Image(3, 1, Color3(2.0f)), path);
    EXPECT_EQ(read_image(path), Image(3, 1, Color3(2.0f)));
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.pfm"});
    // A relative path in the current folder works too (no folder part in the temporary name).
    const fs::path cwd = fs::current_path();
    fs::current_path(dir.path());
    write_image(Image(1, 1, Color3(3.0f)), "rel.exr");
    fs::current_path(cwd);
    EXPECT_EQ(read_image(dir.file("rel.exr")), Image(1, 1, Color3(3.0f)));
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"out.pfm", "rel.exr"}));
}

TEST(ImageIo, FailedWriteLeavesExistingFileIntact) {
    ScratchDir dir;
    for (const char* name : {"keep.exr", "keep.pfm", "keep.hdr", "keep.png"}) {
        const std::string path = dir.file(name);
        write_image(test::test_image(4, 4), path);
        const std::string before = test::file_contents(path);
        ASSERT_FALSE(before.empty());
        EXPECT_THROW(write_image(Image(0, 4), path), Error) << name;
        EXPECT_THROW(write_image(Image(), path), Error) << name;
        EXPECT_EQ(test::file_contents(path), before) << name;
    }
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"keep.exr", "keep.hdr", "keep.pfm", "keep.png"}));
}

TEST(ImageIo, FailedRenameRemovesTheTemporary) {
    ScratchDir dir;
    // The target is a non-empty folder: the temporary is written, the rename fails.
    fs::create_directory(dir.file("out.exr"));
    test::write_contents(dir.file("out.exr/inside"), "precious");
    const std::string message =
        error_of([&] { write_image(Image(2, 2, Color3(1.0f)), dir.file("out.exr")); });
    EXPECT_EQ(message.rfind("cannot write \"" + dir.file("out.exr") + "\": ", 0), 0u) << message;
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.exr"});
    EXPECT_TRUE(fs::is_directory(dir.file("out.exr")));
    EXPECT_EQ(test::file_contents(dir.file("out.exr/inside")), "precious");
}

TEST(ImageIo, TemporaryNameIsHiddenNextToTarget) {
    const std::string a = temporary_path_for("some/dir/out.png");
    const std::string b = temporary_path_for("some/dir/out.png");
    EXPECT_EQ(a.rfind("some/dir/.out.png.tmp-", 0), 0u) << a;
    EXPECT_NE(a, b);
    EXPECT_EQ(temporary_path_for("x.exr").rfind(".x.exr.tmp-", 0), 0u);
}

} // namespace
} // namespace illum
