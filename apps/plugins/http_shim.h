// The HTTP server of `illum render --serve`, behind an interface that the module illum-http.so provides
// (http_shim.cpp, on cpp-httplib). The program loads the module only when a preview is asked for
// (apps/illum/preview_server.cpp), so an ordinary run does not load cpp-httplib and the OpenSSL and Brotli
// libraries it links: they cost about two milliseconds of start-up (docs/performance.md, "Start-up without
// MPI and the HTTP server"). Program and module are built together by one compiler, so C++ types cross
// between them.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace illum::plugin {

struct HttpRequest {
    std::multimap<std::string, std::string> params; // the query's parameters
    bool has(const std::string& name) const { return params.count(name) > 0; }
    // The first value of the parameter `name` ("" when absent).
    std::string get(const std::string& name) const {
        auto it = params.find(name);
        return it == params.end() ? std::string() : it->second;
    }
};

struct HttpResponse {
    int status = 200;
    std::string body, content_type;
    std::vector<std::pair<std::string, std::string>> headers;
    void set_content(std::string content, std::string type) {
        body = std::move(content);
        content_type = std::move(type);
    }
    void set_header(std::string name, std::string value) {
        headers.emplace_back(std::move(name), std::move(value));
    }
};

using HttpHandler = std::function<void(const HttpRequest&, HttpResponse&)>;

class HttpServer {
public:
    virtual ~HttpServer() = default;
    // Answers GET requests for `path` (before listening starts).
    virtual void get(const std::string& path, HttpHandler handler) = 0;
    // The port bound on `host`, or a value <= 0 when none could be.
    virtual int bind_to_any_port(const std::string& host) = 0;
    virtual bool bind_to_port(const std::string& host, int port) = 0;
    // Serves until stop() (call on a thread of its own).
    virtual void listen_after_bind() = 0;
    virtual void stop() = 0;
};

} // namespace illum::plugin

extern "C" {
// The module's one entry point (dlsym name "illum_http_server_new"): a new server, owned by the caller.
illum::plugin::HttpServer* illum_http_server_new(int version);
}

constexpr int kIllumHttpShimVersion = 1;
