// The live preview of `illum render --serve HOST:PORT`: a small HTTP server (cpp-httplib, Debian's, in the
// module illum-http.so that the first preview loads: apps/plugins/http_shim.h) on its
// own thread that serves one page (preview_page.h) and the render's state: the image so far as PNG (with
// the page's exposure and tone map) or EXR (linear, to save), the linear radiance of a pixel, and the
// progress, long-polled (/status?after=FRAME answers when a newer frame has landed). It binds to the loopback
// address unless a host is given, answers only its own routes, and stops when the render command is done with
// it.
#pragma once

#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "illum/image/image.h"
#include "illum/render/render_preview.h"

#include "../plugins/http_shim.h"

namespace illum::cli {

// "PORT" (on 127.0.0.1) or "HOST:PORT"; port 0 picks a free one. Throws illum::Error otherwise.
struct ServeAddress {
    std::string host;
    int port = 0;
};
ServeAddress parse_serve_address(const std::string& text);

class PreviewServer final : public RenderPreview {
public:
    // Binds and starts serving; throws illum::Error when the address cannot be bound. total_spp: the samples
    // per pixel the render will take (0 when a time budget decides), reported before the first pass lands.
    PreviewServer(const ServeAddress& address, int width, int height, int total_spp);
    ~PreviewServer() override;

    // http://host:port/
    std::string url() const;
    void frame(Image image, int spp, int total_spp, double fraction) override;
    // The render is over: the page shows the final image and says so.
    void finish();
    // Stops serving and joins the server's thread.
    void stop();

private:
    struct State {
        Image image;
        int spp = 0, total_spp = 0, frames = 0;
        double fraction = 0, elapsed = 0;
        bool done = false;
    };
    State snapshot() const;
    // The status once frame `after` has been superseded (or the render is done), waiting up to 2 s: the
    // page long-polls, so frames reach it as they land.
    std::string status_json(int after);

    ServeAddress address_;
    std::unique_ptr<plugin::HttpServer> server_; // from illum-http.so
    std::thread thread_;
    mutable std::mutex mutex_;
    std::condition_variable changed_; // a frame landed, the render ended, or the server is stopping
    bool stopping_ = false;
    State state_;
    std::chrono::steady_clock::time_point start_;
};

} // namespace illum::cli
