// Bad grid-medium parameters throw illum::Error with a message naming the problem, positioned at the
// parameter (or at the directive when the parameter is missing); nothing crashes.
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <limits>
#include <unistd.h>

#include <iostream>
#include <nanovdb/util/GridBuilder.h>
#include <nanovdb/util/IO.h>

#include "medium_test_util.h"

namespace illum {
namespace {

using test::DescBuilder;

// Expects create() to throw an Error whose message contains `text`, at source line `line`.
void expect_error(const DescBuilder& b, const std::string& text, int line) {
    try {
        b.create();
        ADD_FAILURE() << "no error; expected \"" << text << "\"";
    } catch (const Error& e) {
        EXPECT_NE(e.message().find(text), std::string::npos) << "message: " << e.message();
        EXPECT_EQ(e.where().line, line) << "message: " << e.message();
        EXPECT_EQ(e.where().file, "media.pbrt");
    }
}

DescBuilder grid(std::vector<double> density, int nx = 2, int ny = 1, int nz = 1) {
    DescBuilder b("uniformgrid");
    b.res(nx, ny, nz).f("density", std::move(density));
    return b;
}

TEST(BadInput, UniformGrid) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    {
        DescBuilder b = grid({1, 2, 3});
        expect_error(b, "\"density\" has 3 values; expected nx * ny * nz = 2", b.line_of("density"));
    }
    {
        DescBuilder b = grid({1, -2});
        expect_error(b, "\"density\" has a negative value", b.line_of("density"));
    }
    {
        DescBuilder b = grid({1, nan});
        expect_error(b, "not a finite number", b.line_of("density"));
    }
    {
        DescBuilder b = grid({1}, 0, 1, 1);
        expect_error(b, "\"nx\" must be at least 1", b.line_of("nx"));
    }
    {
        DescBuilder b = grid({1}, 1, 1, -3);
        expect_error(b, "\"nz\" must be at least 1", b.line_of("nz"));
    }
    {
        DescBuilder b = grid({1, 1});
        b.p3("p0", {0, 0, 0}).p3("p1", {1, 0, 1});
        expect_error(b, "\"p0\" must be below \"p1\"", b.line_of("p1"));
    }
    {
        DescBuilder b = grid({1, 1});
        b.p3("p0", {2, 0, 0});
        expect_error(b, "\"p0\" must be below \"p1\"", b.line_of("p0"));
    }
    {
        DescBuilder b = grid({1, 1});
        b.f("temperature", {1000});
        expect_error(b, "\"temperature\" has 1 values", b.line_of("temperature"));
    }
    {
        DescBuilder b = grid({1, 1});
        b.f("temperature", {1000, 2000}).rgb("Le", {1, 1, 1});
        expect_error(b, "both \"Le\" and \"temperature\"", b.line_of("Le"));
    }
    {
        DescBuilder b = grid({1, 1});
        b.f("Lescale", {2});
        expect_error(b, "\"Lescale\" has 1 values", b.line_of("Lescale"));
    }
    {
        DescBuilder b = grid({1, 1});
        b.f("Lescale", {2, -1});
        expect_error(b, "\"Lescale\" has a negative value", b.line_of("Lescale"));
    }
    {
        DescBuilder b = grid({1, 1});
        b.rgb("sigma_a", {1, -1, 1});
        expect_error(b, "must be finite and non-negative", b.line_of("sigma_a"));
    }
    {
        DescBuilder b = grid({1, 1});
        b.f("g", {1});
        expect_error(b, "\"g\" must lie in (-1, 1)", b.line_of("g"));
    }
    {
        DescBuilder b("uniformgrid");
        expect_error(b, "no \"density\" values", 1);
    }
}

TEST(BadInput, RGBGrid) {
    {
        DescBuilder b("rgbgrid");
        b.rgb("sigma_a", {1, 1});
        expect_error(b, "needs a multiple of 3 values", b.line_of("sigma_a"));
    }
    {
        DescBuilder b("rgbgrid");
        b.res(2, 1, 1).rgb("sigma_a", {1, 1, 1, 1, -1, 1});
        expect_error(b, "must be finite and non-negative", b.line_of("sigma_a"));
    }
    {
        DescBuilder b("rgbgrid");
        b.res(2, 1, 1).rgb("sigma_s", {1, 1, 1});
        expect_error(b, "1 values; expected nx * ny * nz = 2", b.line_of("sigma_s"));
    }
    {
        DescBuilder b("rgbgrid");
        b.rgb("sigma_a", {1, 1, 1}).rgb("sigma_s", {1, 1, 1, 2, 2, 2});
        expect_error(b, "\"sigma_a\" has 1 values and \"sigma_s\" 2", b.line_of("sigma_s"));
    }
    {
        DescBuilder b("rgbgrid");
        b.rgb("sigma_s", {1, 1, 1}).rgb("Le", {1, 1, 1});
        expect_error(b, "\"Le\" needs \"sigma_a\"", b.line_of("Le"));
    }
    {
        DescBuilder b("rgbgrid");
        b.f("sigma_a", {1, 1, 1});
        expect_error(b, "expected rgb", b.line_of("sigma_a"));
    }
    {
        DescBuilder b("rgbgrid");
        b.f("scale", {1});
        expect_error(b, "needs \"sigma_a\" and/or \"sigma_s\"", 1);
    }
}

TEST(BadInput, Cloud) {
    DescBuilder b("cloud");
    b.f("density", {-1});
    expect_error(b, "\"density\" must be non-negative", b.line_of("density"));
    DescBuilder c("cloud");
    c.p3("p1", {1, 1, -1});
    expect_error(c, "\"p0\" must be below \"p1\"", c.line_of("p1"));
}

std::string temp_path(const std::string& name) {
    return (std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()) + ".nvdb"))
        .string();
}

TEST(BadInput, NanoVDB) {
    {
        DescBuilder b("nanovdb");
        expect_error(b, "needs \"string filename\"", 1);
    }
    {
        DescBuilder b("nanovdb");
        b.s("filename", "/nonexistent/cloud.nvdb");
        expect_error(b, "cannot read NanoVDB file \"/nonexistent/cloud.nvdb\"", b.line_of("filename"));
    }
    std::string path = temp_path("illum-bad-vdb");
    {
        // Not a NanoVDB file at all.
        std::ofstream(path)
            << "this is not a nanovdb file, just some text padding it out to a few dozen bytes";
        DescBuilder b("nanovdb");
        b.s("filename", path);
        EXPECT_THROW(b.create(), Error);
    }
    auto make = [](float value, const std::string& name) {
        nanovdb::GridBuilder<float> builder(0.0f, nanovdb::GridClass::FogVolume);
        auto acc = builder.getAccessor();
        for (int i = 0; i < 3; ++i) acc.setValue(nanovdb::Coord(i, 0, 0), value);
        return builder.getHandle<>(1.0, nanovdb::Vec3d(0), name);
    };
    {
        nanovdb::io::writeGrid(path, make(1, "smoke"));
        DescBuilder b("nanovdb");
        b.s("filename", path);
        expect_error(b, "has no grid named \"density\"", b.line_of("filename"));
    }
    {
        nanovdb::io::writeGrid(path, make(-1, "density"));
        DescBuilder b("nanovdb");
        b.s("filename", path);
        expect_error(b, "negative or non-finite values", b.line_of("filename"));
    }
    {
        // Truncated: the header promises more bytes than the file has.
        nanovdb::io::writeGrid(path, make(1, "density"));
        auto size = std::filesystem::file_size(path);
        std::filesystem::resize_file(path, size / 2);
        DescBuilder b("nanovdb");
        b.s("filename", path);
        EXPECT_THROW(b.create(), Error);
    }
    std::filesystem::remove(path);
}

} // namespace
} // namespace illum
