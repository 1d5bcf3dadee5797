// illum-http.so: http_shim.h's server on cpp-httplib.
#include "http_shim.h"

#include <httplib.h>

namespace illum::plugin {

namespace {

class HttplibServer final : public HttpServer {
public:
    void get(const std::string& path, HttpHandler handler) override {
        server_.Get(path,
                    [handler = std::move(handler)](const httplib::Request& req, httplib::Response& res) {
                        HttpRequest request;
                        for (const auto& [name, value] : req.params) request.params.emplace(name, value);
                        HttpResponse response;
                        handler(request, response);
                        res.status = response.status;
                        for (const auto& [name, value] : response.headers) res.set_header(name, value);
                        res.set_content(response.body, response.content_type);
                    });
    }
    int bind_to_any_port(const std::string& host) override { return server_.bind_to_any_port(host); }
    bool bind_to_port(const std::string& host, int port) override { return server_.bind_to_port(host, port); }
    void listen_after_bind() override { server_.listen_after_bind(); }
    void stop() override { server_.stop(); }

private:
    httplib::Server server_;
};

} // namespace

} // namespace illum::plugin

extern "C" __attribute__((visibility("default"))) illum::plugin::HttpServer*
illum_http_server_new(int version) {
    if (version != kIllumHttpShimVersion) return nullptr;
    return new illum::plugin::HttplibServer();
}
