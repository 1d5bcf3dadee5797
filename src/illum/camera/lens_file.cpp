#include "illum/camera/lens_file.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

namespace illum {

bool LensPrescription::dispersive() const {
    for (const LensSurfaceSpec& s : surfaces)
        if (s.abbe > 0) return true;
    return false;
}

namespace {

struct Token {
    std::string_view text;
    int column; // 1-based
};

std::vector<Token> split(std::string_view line) {
    std::vector<Token> tokens;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        std::size_t j = i;
        while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
        if (j > i) tokens.push_back({line.substr(i, j - i), int(i) + 1});
        i = j;
    }
    return tokens;
}

} // namespace

LensPrescription parse_lens_file(const std::string& text, const std::string& name) {
    LensPrescription lens;
    std::istringstream in(text);
    std::string line;
    for (int line_no = 1; std::getline(in, line); ++line_no) {
        std::string_view body(line);
        body = body.substr(0, body.find('#'));
        std::vector<Token> tokens = split(body);
        if (tokens.empty()) continue;
        SourceLocation loc{name, line_no, tokens[0].column};
        if (tokens.size() != 4 && tokens.size() != 5)
            throw Error(loc,
                        fmt::format("a lens surface needs 4 numbers (radius, thickness, index, aperture) "
                                    "and an optional Abbe number, this line has {}",
                                    tokens.size()));
        double v[5] = {0, 0, 0, 0, 0};
        for (std::size_t k = 0; k < tokens.size(); ++k) {
            const Token& t = tokens[k];
            auto [end, ec] = std::from_chars(t.text.data(), t.text.data() + t.text.size(), v[k]);
            if (ec != std::errc() || end != t.text.data() + t.text.size() || !std::isfinite(v[k]))
                throw Error({name, line_no, t.column}, fmt::format("\"{}\" is not a number", t.text));
        }
        LensSurfaceSpec s{v[0], v[1], v[2], v[3], v[4], loc};
        auto fail = [&](int k, const std::string& what) {
            throw Error({name, line_no, tokens[k].column}, what);
        };
        if (s.thickness_mm < 0) fail(1, "a lens thickness must not be negative");
        if (!(s.aperture_mm > 0)) fail(3, "a lens aperture diameter must be positive");
        if (s.n_d != 0 && s.n_d < 1) fail(2, fmt::format("index of refraction {} is below 1", s.n_d));
        if (s.abbe < 0) fail(4, "an Abbe number must not be negative");
        if (s.abbe > 0 && s.n_d <= 1) fail(4, "an Abbe number needs a glass (index above 1)");
        if (!s.is_stop() && s.aperture_mm > 2 * std::abs(s.radius_mm))
            fail(3, fmt::format("aperture diameter {} mm exceeds the sphere of radius {} mm", s.aperture_mm,
                                s.radius_mm));
        lens.surfaces.push_back(s);
    }
    if (lens.surfaces.empty()) throw Error(SourceLocation{name, 0, 0}, "lens file has no surfaces");
    return lens;
}

LensPrescription read_lens_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(fmt::format("cannot read lens file \"{}\": {}", path, std::strerror(errno)));
    std::stringstream ss;
    ss << in.rdbuf();
    return parse_lens_file(ss.str(), path);
}

} // namespace illum
