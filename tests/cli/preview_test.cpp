// The live preview of `illum render --serve` (apps/illum/preview_server.*): its routes answer while the
// render runs (status, PNG frames, a pixel's radiance, the EXR) and nothing else; it binds to loopback by
// default and stops with the render; and in a real headless Chromium the page loads, its image updates,
// and a pixel read through the page equals the written image's.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <httplib.h>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <thread>
#include <unistd.h>

#include "cli_support.h"
#include "illum/image/exr.h"
#include "illum/image/image_io.h"
#include "illum/image/ldr.h"

namespace {

namespace fs = std::filesystem;
using cli_support::read_bytes;

class Preview : public testing::Test {
protected:
    void SetUp() override {
        dir_ = cli_support::fresh_test_folder("preview");
    }
    void TearDown() override { fs::remove_all(dir_); }

    // Starts `illum render ARGS --serve 0` in the background, waits for its "preview: URL" line and
    // returns the URL (empty on failure); finish() waits for the process and returns its exit code.
    std::string start(const std::string& args) {
        std::string cmd = "cd '" + dir_.string() + "' && '" + ILLUM_CLI_PATH + "' render " + args +
                          " --serve 0 2> render.err & echo $!";
        FILE* p = popen(cmd.c_str(), "r");
        if (!p) return {};
        if (std::fscanf(p, "%d", &pid_) != 1) pid_ = 0;
        pclose(p);
        for (int i = 0; i < 200; ++i) {
            std::string err = read_bytes(dir_ / "render.err");
            if (auto at = err.find("preview: "); at != std::string::npos && err.find('\n', at) != std::string::npos)
                return err.substr(at + 9, err.find('\n', at) - at - 9);
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
        return {};
    }
    // Whether the background render has ended (within `seconds`).
    bool ended_within(double seconds) {
        auto t0 = std::chrono::steady_clock::now();
        while (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() < seconds) {
            if (pid_ <= 0 || ::kill(pid_, 0) != 0) return true;
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
        return false;
    }
    fs::path dir_;
    int pid_ = 0;
};

// The server's address as httplib wants it: host and port of "http://host:port/".
std::pair<std::string, int> host_port(const std::string& url) {
    std::string rest = url.substr(7, url.size() - 8);
    auto colon = rest.rfind(':');
    return {rest.substr(0, colon), std::stoi(rest.substr(colon + 1))};
}

TEST_F(Preview, ServesTheRenderWhileItRuns) {
    // out.pfm: float, as the preview serves (an EXR output is half by default, as pbrt-v4 writes its film).
    std::string url = start("--resolution 64x48 --spp 64 --serve-linger 3 -q -o out.pfm");
    ASSERT_FALSE(url.empty()) << read_bytes(dir_ / "render.err");
    auto [host, port] = host_port(url);
    EXPECT_EQ(host, "127.0.0.1") << "loopback unless told otherwise";
    httplib::Client client(host, port);

    auto page = client.Get("/");
    ASSERT_TRUE(page);
    EXPECT_EQ(page->status, 200);
    EXPECT_NE(page->body.find("<img id=\"view\""), std::string::npos);

    auto status = client.Get("/status");
    ASSERT_TRUE(status);
    auto st = nlohmann::json::parse(status->body);
    EXPECT_EQ(st["width"], 64);
    EXPECT_EQ(st["height"], 48);
    EXPECT_EQ(st["total_spp"], 64);

    auto png = client.Get("/frame.png?exposure=1.5&tonemap=aces");
    ASSERT_TRUE(png);
    EXPECT_EQ(png->status, 200);
    illum::Image frame = illum::decode_ldr(
        std::span(reinterpret_cast<const unsigned char*>(png->body.data()), png->body.size()), "frame.png");
    EXPECT_EQ(frame.width(), 64);
    EXPECT_EQ(frame.height(), 48);

    auto pixel = client.Get("/pixel?x=3&y=4");
    ASSERT_TRUE(pixel);
    EXPECT_EQ(pixel->status, 200);
    EXPECT_TRUE(nlohmann::json::parse(pixel->body).contains("r"));
    for (const char* bad : {"/pixel?x=64&y=0", "/pixel?x=-1&y=0", "/pixel?x=a&y=1", "/frame.png?tonemap=x",
                            "/frame.png?exposure=nan"}) {
        auto r = client.Get(bad);
        ASSERT_TRUE(r) << bad;
        EXPECT_EQ(r->status, 400) << bad;
    }
    for (const char* other : {"/etc/passwd", "/../render.err", "/out.exr", "/index.html"}) {
        auto r = client.Get(other);
        ASSERT_TRUE(r) << other;
        EXPECT_EQ(r->status, 404) << other << ": only its own routes";
    }

    // After the render: done, and the EXR served holds the image written.
    for (int i = 0; i < 200 && !nlohmann::json::parse(client.Get("/status")->body)["done"]; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    auto exr = client.Get("/image.exr");
    ASSERT_TRUE(exr);
    illum::Image served = illum::decode_exr(
        std::span(reinterpret_cast<const unsigned char*>(exr->body.data()), exr->body.size()), "image.exr");
    EXPECT_TRUE(served == illum::read_image((dir_ / "out.pfm").string()));

    // It stops with the render (after the linger): the process ends and the port closes.
    EXPECT_TRUE(ended_within(15));
    httplib::Client after(host, port);
    after.set_connection_timeout(1);
    EXPECT_FALSE(after.Get("/status"));
}

// With a preview the loops render in passes of one sample per pixel; the samples, and so the image, are the
// same as without one.
TEST_F(Preview, LeavesTheImageAlone) {
    for (std::string integrator : {"path", "bdpt", "lightpath", "sppm", "vcm"}) {
        SCOPED_TRACE(integrator);
        std::string args = "render --resolution 24x16 --spp 5 --seed 3 -q --integrator " + integrator;
        ASSERT_EQ(cli_support::illum(args + " -o plain.exr", dir_).exit_code, 0);
        cli_support::CliRun r = cli_support::illum(args + " --serve 0 -o served.exr", dir_);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_TRUE(illum::read_image((dir_ / "plain.exr").string()) ==
                    illum::read_image((dir_ / "served.exr").string()));
    }
}

TEST_F(Preview, BadAddressIsAnError) {
    cli_support::CliRun r = cli_support::illum("render --resolution 8x8 --spp 1 --serve 127.0.0.1:99999 -o o.exr",
                                               dir_);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--serve \"127.0.0.1:99999\""), std::string::npos) << r.err;
    cli_support::CliRun r2 = cli_support::illum("render --resolution 8x8 --spp 1 --serve 192.0.2.1:8080 -o o.exr",
                                                dir_);
    EXPECT_EQ(r2.exit_code, 2);
    EXPECT_NE(r2.err.find("cannot serve the preview on 192.0.2.1:8080"), std::string::npos) << r2.err;
}

// A real browser: Debian's Chromium, headless. The page polls while the render runs (several frames
// load), then reads pixel (64, 40) through /pixel and shows it; it must equal the EXR's pixel exactly.
TEST_F(Preview, ChromiumSeesTheImageConverge) {
    const char* chromium = nullptr;
    for (const char* c : {"/usr/bin/chromium", "/usr/bin/chromium-browser", "/usr/bin/google-chrome"})
        if (fs::exists(c)) chromium = c;
    if (!chromium) GTEST_SKIP() << "no Chromium (scripts/setup.sh installs Debian's)";
    // Long enough (about 10 s on two idle cores) that the browser, which under a loaded machine took longer
    // to start than a 512-spp render took to finish, sees the image while it still changes.
    std::string url = start("--resolution 128x96 --spp 4096 --serve-linger 30 -q -o out.pfm");
    ASSERT_FALSE(url.empty()) << read_bytes(dir_ / "render.err");
    std::string cmd = std::string("'") + chromium + "' --headless --no-sandbox --disable-gpu --no-first-run " +
                      "--user-data-dir='" + (dir_ / "profile").string() +
                      "' --virtual-time-budget=120000 --dump-dom '" + url + "?probe=64,40'";
    cli_support::CliRun r = cli_support::run_in(cmd, dir_);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto element = [&](const std::string& id) {
        std::string open = "<pre id=\"" + id + "\">";
        auto a = r.out.find(open);
        if (a == std::string::npos) return std::string();
        a += open.size();
        return r.out.substr(a, r.out.find("</pre>", a) - a);
    };
    int frames = std::atoi(element("frames").c_str());
    EXPECT_GE(frames, 2) << "the image must update while rendering\n" << r.out;
    int x = -1, y = -1, spp = 0;
    float rgb[3] = {-1, -1, -1};
    ASSERT_EQ(std::sscanf(element("probe").c_str(), "%d %d %f %f %f %d", &x, &y, &rgb[0], &rgb[1], &rgb[2], &spp), 6)
        << r.out;
    EXPECT_EQ(x, 64);
    EXPECT_EQ(y, 40);
    EXPECT_EQ(spp, 4096);
    ::kill(pid_, SIGTERM); // no need to linger
    ASSERT_TRUE(ended_within(15));
    illum::Image exr = illum::read_image((dir_ / "out.pfm").string());
    for (int c = 0; c < 3; ++c) EXPECT_EQ(rgb[c], exr(64, 40)[c]) << "channel " << c;
    EXPECT_GT(rgb[0], 0.0f);
}

} // namespace
