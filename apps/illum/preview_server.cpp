#include "preview_server.h"

#include <cstdio>
#include <fmt/core.h>

#include "illum/image/exr.h"
#include "illum/image/ldr.h"
#include "illum/image/tonemap.h"
#include "illum/util/error.h"
#include "load_module.h"
#include "preview_page.h"

namespace illum::cli {

namespace {

using plugin::HttpRequest;
using plugin::HttpResponse;

// A new server from the module illum-http.so (loaded on the first preview).
std::unique_ptr<plugin::HttpServer> new_http_server() {
    std::string error;
    auto make = reinterpret_cast<plugin::HttpServer* (*)(int)>(
        plugin::module_symbol("illum-http.so", "illum_http_server_new", plugin::ModuleScope::Local, &error));
    plugin::HttpServer* server = make ? make(kIllumHttpShimVersion) : nullptr;
    if (make && !server) error = "illum-http.so is from another build";
    if (!server) throw Error("cannot serve the preview: " + error);
    return std::unique_ptr<plugin::HttpServer>(server);
}

// A query parameter as a number, or `fallback` when absent; false when present but not a number.
bool query_number(const HttpRequest& req, const char* name, double fallback, double& value) {
    value = fallback;
    if (!req.has(name)) return true;
    const std::string s = req.get(name);
    char* end = nullptr;
    value = std::strtod(s.c_str(), &end);
    return !s.empty() && end && *end == '\0' && std::isfinite(value);
}

void bad_request(HttpResponse& res, const std::string& why) {
    res.status = 400;
    res.set_content(why + "\n", "text/plain");
}

} // namespace

ServeAddress parse_serve_address(const std::string& text) {
    ServeAddress a{"127.0.0.1", -1};
    std::string port = text;
    if (auto colon = text.rfind(':'); colon != std::string::npos) {
        a.host = text.substr(0, colon);
        port = text.substr(colon + 1);
    }
    char* end = nullptr;
    long p = std::strtol(port.c_str(), &end, 10);
    if (a.host.empty() || port.empty() || *end != '\0' || p < 0 || p > 65535)
        throw Error("--serve \"" + text + "\" is not PORT or HOST:PORT (for example 127.0.0.1:8080)");
    a.port = int(p);
    return a;
}

PreviewServer::PreviewServer(const ServeAddress& address, int width, int height, int total_spp)
    : address_(address), server_(new_http_server()), start_(std::chrono::steady_clock::now()) {
    state_.image = Image(width, height);
    state_.total_spp = total_spp;
    plugin::HttpServer& s = *server_;
    s.get("/", [](const HttpRequest&, HttpResponse& res) {
        res.set_content(kPreviewPage, "text/html; charset=utf-8");
    });
    s.get("/status", [this](const HttpRequest& req, HttpResponse& res) {
        double after = -1;
        if (!query_number(req, "after", -1, after)) return bad_request(res, "after must be a frame number");
        res.set_header("Cache-Control", "no-store");
        res.set_content(status_json(int(after)), "application/json");
    });
    s.get("/frame.png", [this](const HttpRequest& req, HttpResponse& res) {
        double exposure = 0;
        if (!query_number(req, "exposure", 0, exposure)) return bad_request(res, "exposure must be a number");
        auto tonemap = tonemap_from_string(req.has("tonemap") ? req.get("tonemap") : "clamp");
        if (!tonemap) return bad_request(res, "tonemap must be clamp, reinhard or aces");
        State st = snapshot();
        res.set_header("Cache-Control", "no-store");
        res.set_content(encode_png(st.image, *tonemap, float(exposure)), "image/png");
    });
    s.get("/image.exr", [this](const HttpRequest&, HttpResponse& res) {
        State st = snapshot();
        res.set_header("Content-Disposition", "attachment; filename=\"illum-preview.exr\"");
        res.set_content(encode_exr(st.image), "image/x-exr");
    });
    s.get("/pixel", [this](const HttpRequest& req, HttpResponse& res) {
        double x = -1, y = -1;
        State st = snapshot();
        if (!query_number(req, "x", -1, x) || !query_number(req, "y", -1, y) || x != std::floor(x) ||
            y != std::floor(y) || x < 0 || y < 0 || x >= st.image.width() || y >= st.image.height())
            return bad_request(res, "x and y must be pixel coordinates inside the image");
        Color3 c = st.image(int(x), int(y));
        res.set_header("Cache-Control", "no-store");
        // %.9g: enough digits that the page's numbers are the image's floats exactly.
        res.set_content(fmt::format("{{\"x\": {}, \"y\": {}, \"r\": {:.9g}, \"g\": {:.9g}, \"b\": {:.9g}, "
                                    "\"spp\": {}}}",
                                    int(x), int(y), c.r, c.g, c.b, st.spp),
                        "application/json");
    });
    if (address.port == 0) {
        int port = s.bind_to_any_port(address.host);
        if (port <= 0) throw Error("cannot serve the preview on " + address.host + ": no free port");
        address_.port = port;
    } else if (!s.bind_to_port(address.host, address.port)) {
        throw Error(
            fmt::format("cannot serve the preview on {}:{} (in use, or not an address of this machine)",
                        address.host, address.port));
    }
    thread_ = std::thread([this] { server_->listen_after_bind(); });
}

PreviewServer::~PreviewServer() { stop(); }

std::string PreviewServer::url() const { return fmt::format("http://{}:{}/", address_.host, address_.port); }

void PreviewServer::frame(Image image, int spp, int total_spp, double fraction) {
    double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::lock_guard lock(mutex_);
    state_.image = std::move(image);
    state_.spp = spp;
    state_.total_spp = total_spp;
    state_.fraction = fraction;
    state_.elapsed = elapsed;
    ++state_.frames;
    changed_.notify_all();
}

void PreviewServer::finish() {
    std::lock_guard lock(mutex_);
    state_.done = true;
    state_.fraction = 1;
    changed_.notify_all();
}

void PreviewServer::stop() {
    if (!thread_.joinable()) return;
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
        changed_.notify_all();
    }
    server_->stop();
    thread_.join();
}

PreviewServer::State PreviewServer::snapshot() const {
    std::lock_guard lock(mutex_);
    return state_;
}

std::string PreviewServer::status_json(int after) {
    std::unique_lock lock(mutex_);
    changed_.wait_for(lock, std::chrono::seconds(2),
                      [&] { return state_.frames > after || state_.done || stopping_; });
    const State& st = state_;
    const double pixels = double(st.image.width()) * st.image.height();
    const double rate = st.elapsed > 0 ? st.spp * pixels / st.elapsed : 0;
    const double eta = st.done ? 0 : st.fraction > 0 ? st.elapsed * (1 - st.fraction) / st.fraction : -1;
    return fmt::format(
        "{{\"width\": {}, \"height\": {}, \"spp\": {}, \"total_spp\": {}, \"frames\": {}, "
        "\"fraction\": {:.6g}, \"elapsed\": {:.6g}, \"eta\": {:.6g}, \"samples_per_second\": {:.6g}, "
        "\"done\": {}}}",
        st.image.width(), st.image.height(), st.spp, st.total_spp, st.frames, st.fraction, st.elapsed, eta,
        rate, st.done ? "true" : "false");
}

} // namespace illum::cli
