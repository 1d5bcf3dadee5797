#include "illum/scene/pbrt/parser.h"

#include "illum/math/animated_transform.h"
#include "illum/radiometry/color_space.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <sys/stat.h>

#include "illum/scene/pbrt/tokenizer.h"

namespace illum {

namespace {

namespace fs = std::filesystem;

constexpr int kMaxIncludeDepth = 64;

// Reads a regular file whole; nullopt when it cannot be read, with `why` the operating system's reason
// (or "not a regular file" for a device or FIFO, which might never end).
std::optional<std::string> read_text_file(const std::string& path, std::string& why) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) {
        why = std::strerror(errno);
        return std::nullopt;
    }
    struct stat st {};
    if (::fstat(::fileno(f), &st) != 0 || !S_ISREG(st.st_mode)) {
        why = S_ISDIR(st.st_mode) ? std::strerror(EISDIR) : "not a regular file";
        std::fclose(f);
        return std::nullopt;
    }
    std::string text;
    char buf[1 << 16];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof(buf), f)) > 0) text.append(buf, n);
    if (std::ferror(f)) {
        why = std::strerror(errno);
        std::fclose(f);
        return std::nullopt;
    }
    std::fclose(f);
    return text;
}

std::string canonical_path(const std::string& path) {
    std::error_code ec;
    fs::path p = fs::weakly_canonical(fs::path(path), ec);
    if (ec) return fs::path(path).lexically_normal().string();
    return p.string();
}

// Resolves a relative file name against `dir` (the directory of the file that names it).
std::string resolve_path(const std::string& dir, const std::string& name) {
    if (name.empty()) return name;
    fs::path p(name);
    if (p.is_absolute() || dir.empty()) return p.lexically_normal().string();
    return (fs::path(dir) / p).lexically_normal().string();
}

std::string directory_of(const std::string& path) {
    std::string d = fs::path(path).parent_path().string();
    return d.empty() ? std::string(".") : d;
}

// Which of the two current transforms (start and end time) the transform directives change.
enum class Active { All, Start, End };

struct GraphicsState {
    // pbrt-v4's CTM is two transforms, at the start and the end time (TransformTimes); ActiveTransform
    // picks which of them the transform directives change.
    Transform ctm, ctm_end;
    Active active = Active::All;
    bool reverse_orientation = false;
    MaterialRef material;
    int area_light = -1;
    std::string inside_medium, outside_medium;
    SourceLocation medium_loc;
    ParamSet shape_attrs, light_attrs, material_attrs, medium_attrs, texture_attrs;
};

// An open AttributeBegin ('a'), TransformBegin ('t') or ObjectBegin ('o').
struct PushEntry {
    char kind;
    SourceLocation loc;
    GraphicsState saved;
};

struct FileFrame {
    Tokenizer tok;
    std::string dir;       // relative names in this file resolve here
    std::string canonical; // for include-cycle detection
};

const char* push_name(char kind) {
    return kind == 'a' ? "AttributeBegin" : kind == 't' ? "TransformBegin" : "ObjectBegin";
}

class Parser {
public:
    Parser(SceneDesc& scene, const ParseOptions& options) : sc_(scene), options_(options) {}

    void run(std::string text, const std::string& filename, const std::string& dir,
             const std::string& canon) {
        files_.push_back(
            std::make_unique<FileFrame>(FileFrame{Tokenizer(std::move(text), filename), dir, canon}));
        while (!files_.empty()) {
            FileFrame& f = *files_.back();
            Token t = f.tok.next();
            if (t.kind == TokenKind::End) {
                // An included file may hold any part of a scene, but the scene as a whole needs its world:
                // without WorldBegin nothing would be rendered, and pbrt-v4 stops here too.
                if (files_.size() == 1 && !in_world_) f.tok.fail(t, "End of files before WorldBegin");
                files_.pop_back();
                continue;
            }
            if (t.kind != TokenKind::Word)
                f.tok.fail(t, fmt::format("expected a directive, found {} {}", to_string(t.kind), quoted(t)));
            directive(f, t);
        }
        finish();
    }

private:
    // ---- Helpers -------------------------------------------------------------------------------------

    static std::string quoted(const Token& t) {
        std::string_view s = t.text;
        if (s.size() > 40) return fmt::format("{}...", s.substr(0, 40));
        return std::string(s);
    }

    // A recognised feature that illum does not support (or ignores): one warning, or an error under --strict
    // worded as the builder's (build.cpp), so both kinds read alike.
    void warn(const SourceLocation& loc, const std::string& message) {
        if (options_.strict) throw Error(loc, message + " (unsupported; --strict)");
        sc_.warnings.push_back(loc.to_string() + ": " + message);
        sc_.unsupported.push_back({loc, message});
    }

    std::string read_string(FileFrame& f, const Token& directive, const char* what) {
        Token t = f.tok.next();
        if (t.kind != TokenKind::String)
            f.tok.fail(
                t.kind == TokenKind::End ? directive : t,
                fmt::format("{} expects a quoted {}, found {}", directive.text, what, to_string(t.kind)));
        return std::move(t.str);
    }

    // Exactly n numbers, each finite.
    std::vector<double> read_numbers(FileFrame& f, const Token& directive, int n) {
        std::vector<double> v;
        v.reserve(n);
        while (int(v.size()) < n) {
            if (f.tok.peek().kind != TokenKind::Number)
                f.tok.fail(directive,
                           fmt::format("{} expects {} numbers, found {}", directive.text, n, v.size()));
            Token t = f.tok.next();
            if (!std::isfinite(t.number))
                f.tok.fail(t, fmt::format("{}: value {} is not a finite number", directive.text, quoted(t)));
            v.push_back(t.number);
        }
        return v;
    }

    // 16 numbers for Transform/ConcatTransform, in brackets (or bare, as pbrt-v3 accepted).
    Matrix4 read_matrix(FileFrame& f, const Token& directive) {
        std::vector<double> v;
        if (f.tok.peek().kind == TokenKind::LBracket) {
            Token open = f.tok.next();
            while (true) {
                Token t = f.tok.next();
                if (t.kind == TokenKind::RBracket) break;
                if (t.kind != TokenKind::Number)
                    f.tok.fail(t.kind == TokenKind::End ? open : t,
                               fmt::format("{}: expected a number or ']', found {} {}", directive.text,
                                           to_string(t.kind), quoted(t)));
                if (!std::isfinite(t.number))
                    f.tok.fail(t,
                               fmt::format("{}: value {} is not a finite number", directive.text, quoted(t)));
                if (v.size() < 17) v.push_back(t.number);
            }
            if (v.size() != 16)
                f.tok.fail(directive,
                           fmt::format("{} expects 16 numbers, found {}", directive.text,
                                       v.size() > 16 ? std::string("more") : std::to_string(v.size())));
        } else {
            v = read_numbers(f, directive, 16);
        }
        // pbrt gives the matrix column by column: the row-major reading is its transpose.
        Matrix4 m;
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) m.m[r][c] = v[c * 4 + r];
        return m;
    }

    Transform make_transform(FileFrame& f, const Token& directive, const Matrix4& m) {
        auto inv = inverse(m);
        if (!inv) f.tok.fail(directive, fmt::format("{}: the matrix is singular", directive.text));
        return Transform(m, *inv);
    }

    // Sets the active current transforms (start, end or both) to t(current).
    template <typename F>
    void for_active(FileFrame& f, const Token& directive, F t) {
        for (Transform* c : {&gs_.ctm, &gs_.ctm_end}) {
            if ((c == &gs_.ctm && gs_.active == Active::End) ||
                (c == &gs_.ctm_end && gs_.active == Active::Start))
                continue;
            Transform n = t(*c);
            if (!n.matrix().is_finite() || !n.inverse_matrix().is_finite())
                f.tok.fail(directive,
                           fmt::format("{}: the current transform is no longer finite", directive.text));
            *c = n;
        }
    }
    void set_ctm(FileFrame& f, const Token& directive, const Transform& t) {
        for_active(f, directive, [&](const Transform&) { return t; });
    }
    void concat(FileFrame& f, const Token& directive, const Transform& t) {
        for_active(f, directive, [&](const Transform& c) { return c * t; });
    }

    // The end-time transform when it differs from the start one (pbrt-v4's CTMIsAnimated); a moving
    // transform must be affine to be interpolated.
    TransformMotion motion(const SourceLocation& loc) const {
        TransformMotion m;
        if (gs_.ctm == gs_.ctm_end) return m;
        m.animated = true;
        m.end = gs_.ctm_end;
        m.start_time = start_time_;
        m.end_time = end_time_;
        if (!is_affine(gs_.ctm.matrix()) || !is_affine(gs_.ctm_end.matrix()))
            throw Error(loc, "a moving transform must be affine (its last row 0 0 0 1) to be interpolated");
        return m;
    }
    // pbrt-v4 does not move lights, media or textures: it warns and uses the start transform.
    void warn_if_moving(const SourceLocation& loc, const char* what) {
        if (!(gs_.ctm == gs_.ctm_end))
            warn(loc, fmt::format("a moving {} is not supported (as in pbrt-v4): its start transform is used",
                                  what));
    }

    void require_world(FileFrame& f, const Token& d, bool world) {
        if (in_world_ != world)
            f.tok.fail(d, world ? fmt::format("{} is only allowed after WorldBegin", d.text)
                                : fmt::format("{} is only allowed before WorldBegin", d.text));
    }

    // ---- Parameter lists -----------------------------------------------------------------------------

    ParamSet read_params(FileFrame& f, bool resolve_files) {
        ParamSet ps;
        while (f.tok.peek().kind == TokenKind::String) ps.add(read_param(f, resolve_files));
        return ps;
    }

    Param read_param(FileFrame& f, bool resolve_files) {
        Token decl = f.tok.next();
        // "type name"
        std::string_view s = decl.str;
        auto skip_ws = [&](size_t i) {
            while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\n')) ++i;
            return i;
        };
        auto word_end = [&](size_t i) {
            while (i < s.size() && !(s[i] == ' ' || s[i] == '\t' || s[i] == '\n')) ++i;
            return i;
        };
        size_t a0 = skip_ws(0), a1 = word_end(a0), b0 = skip_ws(a1), b1 = word_end(b0);
        if (a0 == a1 || b0 == b1 || skip_ws(b1) != s.size())
            f.tok.fail(decl,
                       fmt::format("bad parameter declaration {} (expected \"type name\")", quoted(decl)));
        std::string type_name(s.substr(a0, a1 - a0));
        Param p;
        p.name = std::string(s.substr(b0, b1 - b0));
        p.loc = f.tok.location(decl);
        // "blackbody" (pbrt-v4) and illum's dispersion formulas "sellmeier" (B1 B2 B3 C1 C2 C3, C in µm²)
        // and "cauchy" (A B, B in µm²) are spectra given by parameters.
        bool blackbody = type_name == "blackbody";
        int formula_values = type_name == "sellmeier" ? 6 : type_name == "cauchy" ? 2 : 0;
        if (blackbody || formula_values) {
            p.type = ParamType::Spectrum;
        } else if (auto t = param_type_from_string(type_name)) {
            p.type = *t;
        } else {
            f.tok.fail(decl, fmt::format("unknown parameter type \"{}\"", type_name));
        }

        // Values: one bare value or a bracketed list.
        std::vector<double>& nums = p.numbers;
        std::vector<std::string>& strs = p.strings;
        int n_bool_words = 0;
        std::optional<Token> first_num, first_str, first_bool;
        auto take = [&](Token& t) {
            switch (t.kind) {
            case TokenKind::Number:
                if (!first_num) first_num = t;
                nums.push_back(t.number);
                return true;
            case TokenKind::String:
                if (!first_str) first_str = t;
                strs.push_back(std::move(t.str));
                return true;
            case TokenKind::Word:
                if (t.text == "true" || t.text == "false") {
                    if (!first_bool) first_bool = t;
                    p.bools.push_back(t.text == "true");
                    ++n_bool_words;
                    return true;
                }
                return false;
            default:
                return false;
            }
        };
        if (f.tok.peek().kind == TokenKind::LBracket) {
            Token open = f.tok.next();
            while (true) {
                Token t = f.tok.next();
                if (t.kind == TokenKind::RBracket) break;
                if (t.kind == TokenKind::End)
                    f.tok.fail(open,
                               fmt::format("unterminated '[' in the values of parameter \"{}\"", p.name));
                if (!take(t))
                    f.tok.fail(
                        t, fmt::format("unexpected {} {} in the values of parameter \"{}\" (missing ']'?)",
                                       to_string(t.kind), quoted(t), p.name));
            }
        } else {
            Token t = f.tok.next();
            if (!take(t))
                f.tok.fail(t.kind == TokenKind::End ? decl : t,
                           fmt::format("missing value for parameter \"{}\", found {} {}", p.name,
                                       to_string(t.kind), quoted(t)));
        }

        const std::string tname = blackbody || formula_values ? type_name : std::string(to_string(p.type));
        auto wrong_kind = [&](const std::optional<Token>& t, const char* expected, const char* found) {
            f.tok.fail(*t, fmt::format("parameter \"{}\" of type {} expects {}, found {} {}", p.name, tname,
                                       expected, found, quoted(*t)));
        };
        auto need_multiple = [&](size_t k) {
            if (nums.size() % k != 0)
                f.tok.fail(decl,
                           fmt::format("parameter \"{}\" of type {} needs a multiple of {} values, has {}",
                                       p.name, tname, k, nums.size()));
        };
        switch (p.type) {
        case ParamType::Float:
        case ParamType::Integer:
        case ParamType::RGB:
        case ParamType::Point2:
        case ParamType::Point3:
        case ParamType::Vector3:
        case ParamType::Normal:
            if (first_str) wrong_kind(first_str, "numbers", "string");
            if (first_bool) wrong_kind(first_bool, "numbers", "bool");
            if (p.type == ParamType::Integer)
                for (double v : nums)
                    if (!(v == std::floor(v) && std::abs(v) <= 2147483647.0))
                        f.tok.fail(decl,
                                   fmt::format("parameter \"{}\" of type integer has the value {}, which "
                                               "is not an integer",
                                               p.name, v));
            if (p.type == ParamType::RGB || p.type == ParamType::Point3 || p.type == ParamType::Vector3 ||
                p.type == ParamType::Normal)
                need_multiple(3);
            if (p.type == ParamType::Point2) need_multiple(2);
            break;
        case ParamType::Bool:
            if (first_num) wrong_kind(first_num, "true or false", "number");
            for (auto& str : strs) {
                if (str != "true" && str != "false")
                    f.tok.fail(*first_str,
                               fmt::format("parameter \"{}\" of type bool: \"{}\" is not true or false",
                                           p.name, str));
            }
            if (!strs.empty()) {
                // Quoted "true"/"false"; keep the order when mixed with bare words.
                p.bools.clear();
                if (n_bool_words > 0)
                    f.tok.fail(*first_str,
                               fmt::format("parameter \"{}\" mixes quoted and bare bool values", p.name));
                for (auto& str : strs) p.bools.push_back(str == "true");
                strs.clear();
            }
            break;
        case ParamType::String:
        case ParamType::Texture:
            if (first_num) wrong_kind(first_num, "quoted strings", "number");
            if (first_bool) wrong_kind(first_bool, "quoted strings", "bool");
            // File names resolve here, once, against the folder of the file that names them (the builder
            // and the create functions never join folders again): pbrt-v4's "filename", "normalmap",
            // "emissionfilename" and "lensfile", the realistic camera's "aperture" image (but for its
            // built-in shapes), and the "file" of illum's measured "merl" material (but for its built-in
            // "synthetic:ALPHA" tables).
            if (resolve_files && p.type == ParamType::String &&
                (p.name == "filename" || p.name == "normalmap" || p.name == "lensfile" || p.name == "file" ||
                 p.name == "aperture" || p.name == "emissionfilename"))
                for (auto& str : strs) {
                    bool builtin =
                        (p.name == "file" && str.rfind("synthetic:", 0) == 0) ||
                        (p.name == "aperture" && (str == "circular" || str == "gaussian" || str == "square" ||
                                                  str == "pentagon" || str == "star"));
                    if (!builtin) str = resolve_path(f.dir, str);
                }
            break;
        case ParamType::Spectrum:
            if (first_bool) wrong_kind(first_bool, "numbers or a quoted name", "bool");
            if (blackbody) {
                if (first_str) wrong_kind(first_str, "one temperature", "string");
                if (nums.size() != 1)
                    f.tok.fail(decl, fmt::format("parameter \"{}\" of type blackbody needs 1 value, has {}",
                                                 p.name, nums.size()));
                strs = {"blackbody"};
            } else if (formula_values) {
                if (first_str) wrong_kind(first_str, "numbers", "string");
                if (int(nums.size()) != formula_values)
                    f.tok.fail(decl, fmt::format("parameter \"{}\" of type {} needs {} values, has {}",
                                                 p.name, type_name, formula_values, nums.size()));
                strs = {type_name};
            } else if (first_str) {
                if (first_num || strs.size() != 1)
                    f.tok.fail(decl,
                               fmt::format("parameter \"{}\" of type spectrum needs wavelength-value pairs "
                                           "or one quoted name",
                                           p.name));
                if (resolve_files) {
                    std::string candidate = resolve_path(f.dir, strs[0]);
                    std::error_code ec;
                    if (!fs::path(strs[0]).is_absolute() && fs::is_regular_file(candidate, ec))
                        strs[0] = candidate;
                }
            } else {
                need_multiple(2);
            }
            break;
        }
        return p;
    }

    static ParamSet with_defaults(ParamSet params, const ParamSet& defaults) {
        for (const Param& p : defaults.params())
            if (!params.has(p.name)) params.add(p);
        return params;
    }

    // ---- Directives ----------------------------------------------------------------------------------

    void directive(FileFrame& f, const Token& d) {
        const std::string_view name = d.text;
        const SourceLocation loc = f.tok.location(d);

        // Transformations.
        if (name == "Translate") {
            auto v = read_numbers(f, d, 3);
            Matrix4 m = Matrix4::identity(), inv = Matrix4::identity();
            for (int i = 0; i < 3; ++i) {
                m.m[i][3] = v[i];
                inv.m[i][3] = -v[i];
            }
            concat(f, d, Transform(m, inv));
        } else if (name == "Scale") {
            auto v = read_numbers(f, d, 3);
            if (v[0] == 0 || v[1] == 0 || v[2] == 0)
                f.tok.fail(d, "Scale by zero makes the transform singular");
            Matrix4 m = Matrix4::identity(), inv = Matrix4::identity();
            for (int i = 0; i < 3; ++i) {
                m.m[i][i] = v[i];
                inv.m[i][i] = 1 / v[i];
            }
            concat(f, d, Transform(m, inv));
        } else if (name == "Rotate") {
            auto v = read_numbers(f, d, 4);
            double len = std::sqrt(v[1] * v[1] + v[2] * v[2] + v[3] * v[3]);
            if (!(len > 0) || !std::isfinite(len))
                f.tok.fail(d, "Rotate: the axis must be a nonzero finite vector");
            Transform r = Transform::rotate(
                float(v[0]), Vector3f(float(v[1] / len), float(v[2] / len), float(v[3] / len)));
            concat(f, d, r);
        } else if (name == "LookAt") {
            auto v = read_numbers(f, d, 9);
            for (double x : v)
                if (!(std::abs(x) <= double(std::numeric_limits<float>::max())))
                    f.tok.fail(d, "LookAt: a value is too large");
            Transform t;
            try {
                t = Transform::look_at(Point3f(float(v[0]), float(v[1]), float(v[2])),
                                       Point3f(float(v[3]), float(v[4]), float(v[5])),
                                       Vector3f(float(v[6]), float(v[7]), float(v[8])));
            } catch (const std::invalid_argument& e) {
                f.tok.fail(d, e.what());
            }
            concat(f, d, t);
        } else if (name == "Transform") {
            Matrix4 m = read_matrix(f, d);
            set_ctm(f, d, make_transform(f, d, m));
        } else if (name == "ConcatTransform") {
            Matrix4 m = read_matrix(f, d);
            concat(f, d, make_transform(f, d, m));
        } else if (name == "Identity") {
            set_ctm(f, d, Transform());
        } else if (name == "CoordinateSystem") {
            std::string n = read_string(f, d, "name");
            named_coords_[n] = {gs_.ctm, gs_.ctm_end};
        } else if (name == "CoordSysTransform") {
            std::string n = read_string(f, d, "name");
            auto it = named_coords_.find(n);
            if (it == named_coords_.end())
                warn(loc, fmt::format("CoordSysTransform: no coordinate system named \"{}\"; ignored", n));
            else {
                // pbrt-v4 sets both transforms, whichever are active.
                gs_.ctm = it->second.first;
                gs_.ctm_end = it->second.second;
            }
        } else if (name == "ActiveTransform") {
            Token t = f.tok.next();
            if (t.kind == TokenKind::Word && t.text == "All")
                gs_.active = Active::All;
            else if (t.kind == TokenKind::Word && t.text == "StartTime")
                gs_.active = Active::Start;
            else if (t.kind == TokenKind::Word && t.text == "EndTime")
                gs_.active = Active::End;
            else
                f.tok.fail(
                    t.kind == TokenKind::End ? d : t,
                    fmt::format("ActiveTransform expects All, StartTime or EndTime, found {}", quoted(t)));
        } else if (name == "TransformTimes") {
            require_world(f, d, false); // pbrt-v4: an option, before WorldBegin
            auto v = read_numbers(f, d, 2);
            if (v[1] < v[0])
                f.tok.fail(d, fmt::format("TransformTimes: the end time {} is before the start time {}", v[1],
                                          v[0]));
            start_time_ = v[0];
            end_time_ = v[1];
        } else if (name == "ReverseOrientation") {
            require_world(f, d, true);
            gs_.reverse_orientation = !gs_.reverse_orientation;
        }

        // Block structure.
        else if (name == "AttributeBegin") {
            require_world(f, d, true);
            stack_.push_back({'a', loc, gs_});
        } else if (name == "AttributeEnd") {
            require_world(f, d, true);
            pop(f, d, 'a');
        } else if (name == "TransformBegin") {
            if (!warned_transform_begin_) {
                warned_transform_begin_ = true;
                warn(loc, "TransformBegin/TransformEnd are deprecated; use AttributeBegin/AttributeEnd");
            }
            GraphicsState saved;
            saved.ctm = gs_.ctm;
            saved.ctm_end = gs_.ctm_end;
            stack_.push_back({'t', loc, std::move(saved)});
        } else if (name == "TransformEnd") {
            pop(f, d, 't');
        } else if (name == "Attribute") {
            require_world(f, d, true);
            std::string target = read_string(f, d, "target");
            ParamSet* dst = target == "shape"      ? &gs_.shape_attrs
                            : target == "light"    ? &gs_.light_attrs
                            : target == "material" ? &gs_.material_attrs
                            : target == "medium"   ? &gs_.medium_attrs
                            : target == "texture"  ? &gs_.texture_attrs
                                                   : nullptr;
            if (!dst)
                f.tok.fail(d,
                           fmt::format("Attribute: unknown target \"{}\" (expected shape, light, material, "
                                       "medium or texture)",
                                       target));
            ParamSet ps = read_params(f, true);
            for (const Param& p : ps.params()) dst->add(p);
        } else if (name == "WorldBegin") {
            if (in_world_)
                f.tok.fail(d, fmt::format("WorldBegin appears twice (first at {})", world_loc_.to_string()));
            in_world_ = true;
            world_loc_ = loc;
            gs_.ctm = gs_.ctm_end = Transform();
            gs_.active = Active::All;
            named_coords_["world"] = {Transform(), Transform()};
        } else if (name == "WorldEnd") {
            require_world(f, d, true);
            warn(loc, "WorldEnd is a pbrt-v3 directive; ignored");
        } else if (name == "Include" || name == "Import") {
            include(f, d);
        } else if (name == "ObjectBegin") {
            require_world(f, d, true);
            Token nt = f.tok.peek();
            std::string n = read_string(f, d, "name");
            if (instance_)
                f.tok.fail(d,
                           fmt::format("ObjectBegin \"{}\" inside the definition of \"{}\" (started at {}): "
                                       "object definitions cannot nest",
                                       n, instance_->name, instance_->loc.to_string()));
            if (sc_.instances.count(n))
                f.tok.fail(nt, fmt::format("object \"{}\" redefined (first defined at {})", n,
                                           sc_.instances[n].loc.to_string()));
            stack_.push_back({'o', loc, gs_});
            InstanceDefinition& def = sc_.instances[n];
            def.name = n;
            def.loc = loc;
            instance_ = &def;
        } else if (name == "ObjectEnd") {
            require_world(f, d, true);
            pop(f, d, 'o');
            instance_ = nullptr;
        } else if (name == "ObjectInstance") {
            require_world(f, d, true);
            std::string n = read_string(f, d, "name");
            if (instance_)
                f.tok.fail(d, fmt::format("ObjectInstance \"{}\" inside the definition of \"{}\": instances "
                                          "cannot nest",
                                          n, instance_->name));
            sc_.instance_uses.push_back({n, gs_.ctm, motion(loc), loc});
        }

        // Rendering options (before WorldBegin).
        else if (name == "Camera") {
            require_world(f, d, false);
            if (!sc_.camera.type.empty())
                warn(loc, fmt::format("a second Camera replaces the one at {}", sc_.camera.loc.to_string()));
            sc_.camera.type = read_string(f, d, "camera type");
            sc_.camera.params = read_params(f, true);
            sc_.camera.loc = loc;
            sc_.camera.camera_from_world = gs_.ctm;
            sc_.camera.motion = motion(loc);
            sc_.camera.medium = gs_.outside_medium;
            sc_.camera.medium_loc = gs_.medium_loc;
            named_coords_["camera"] = {gs_.ctm.inverse(), gs_.ctm_end.inverse()};
        } else if (name == "Film" || name == "Sampler" || name == "PixelFilter" || name == "Integrator" ||
                   name == "Accelerator") {
            require_world(f, d, false);
            EntityDesc e;
            e.type = read_string(f, d, "type");
            e.params = read_params(f, false);
            e.loc = loc;
            if (name == "Film")
                sc_.film = std::move(e);
            else if (name == "Sampler")
                sc_.sampler = std::move(e);
            else if (name == "PixelFilter")
                sc_.filter = std::move(e);
            else if (name == "Integrator")
                sc_.integrator = std::move(e);
            // Accelerator: Embree builds its own; ignored.
        } else if (name == "ColorSpace") {
            sc_.color_space = read_string(f, d, "color space name");
            if (!RGBColorSpace::named(sc_.color_space))
                throw Error(loc,
                            fmt::format("unknown ColorSpace \"{}\" (use srgb, rec2020, aces2065-1 or dci-p3)",
                                        sc_.color_space));
            if (in_world_)
                warn(loc, "ColorSpace after WorldBegin: one color space applies to the whole scene here");
        } else if (name == "Option") {
            // pbrt-v4's parser takes `Option "name" value` (the value a bare true/false, a number or a
            // quoted string) and rejects the typed `Option "type name" value`; illum reads both.
            if (f.tok.peek().kind != TokenKind::String) read_string(f, d, "\"type name\" declaration");
            if (f.tok.peek().str.find_first_of(" \t\n") == std::string::npos) {
                Token decl = f.tok.next();
                Token v = f.tok.next();
                Param p;
                p.name = decl.str;
                p.loc = f.tok.location(decl);
                if (v.kind == TokenKind::Word && (v.text == "true" || v.text == "false")) {
                    p.type = ParamType::Bool;
                    p.bools = {v.text == "true"};
                } else if (v.kind == TokenKind::Number) {
                    p.type = p.name == "seed" ? ParamType::Integer : ParamType::Float;
                    p.numbers = {v.number};
                } else if (v.kind == TokenKind::String) {
                    p.type = ParamType::String;
                    p.strings = {v.str};
                } else {
                    f.tok.fail(v, fmt::format("missing value for Option \"{}\"", p.name));
                }
                sc_.options.add(std::move(p));
            } else {
                sc_.options.add(read_param(f, false));
            }
        }

        // Media.
        else if (name == "MakeNamedMedium") {
            Token nt = f.tok.peek();
            std::string n = read_string(f, d, "name");
            ParamSet ps = with_defaults(read_params(f, true), gs_.medium_attrs);
            MediumDesc m;
            m.name = n;
            m.type = take_type(f, d, ps, n, m.params);
            m.loc = loc;
            m.world_from_medium = gs_.ctm;
            warn_if_moving(loc, "medium");
            if (sc_.media.count(n))
                f.tok.fail(nt, fmt::format("medium \"{}\" redefined (first defined at {})", n,
                                           sc_.media[n].loc.to_string()));
            sc_.media[n] = std::move(m);
        } else if (name == "MediumInterface") {
            std::string inside = read_string(f, d, "medium name");
            std::string outside = inside;
            if (f.tok.peek().kind == TokenKind::String) outside = f.tok.next().str;
            gs_.inside_medium = inside;
            gs_.outside_medium = outside;
            gs_.medium_loc = loc;
        }

        // Materials and textures.
        else if (name == "Material") {
            require_world(f, d, true);
            MaterialDesc m;
            m.type = read_string(f, d, "material type");
            m.params = with_defaults(read_params(f, true), gs_.material_attrs);
            m.loc = loc;
            sc_.materials.push_back(std::move(m));
            gs_.material = MaterialRef{int(sc_.materials.size()) - 1, {}};
        } else if (name == "MakeNamedMaterial") {
            require_world(f, d, true);
            Token nt = f.tok.peek();
            std::string n = read_string(f, d, "name");
            ParamSet ps = with_defaults(read_params(f, true), gs_.material_attrs);
            MaterialDesc m;
            m.name = n;
            m.type = take_type(f, d, ps, n, m.params);
            m.loc = loc;
            if (auto it = sc_.named_materials.find(n); it != sc_.named_materials.end())
                f.tok.fail(nt, fmt::format("named material \"{}\" redefined (first defined at {})", n,
                                           sc_.materials[it->second].loc.to_string()));
            sc_.materials.push_back(std::move(m));
            sc_.named_materials[n] = int(sc_.materials.size()) - 1;
        } else if (name == "NamedMaterial") {
            require_world(f, d, true);
            std::string n = read_string(f, d, "name");
            gs_.material = MaterialRef{-1, n};
            named_material_uses_.push_back({n, loc});
        } else if (name == "Texture") {
            require_world(f, d, true);
            Token nt = f.tok.peek();
            TextureDesc t;
            t.name = read_string(f, d, "texture name");
            Token vt = f.tok.peek();
            t.value_type = read_string(f, d, "texture value type");
            if (t.value_type != "float" && t.value_type != "spectrum")
                f.tok.fail(
                    vt, fmt::format("unknown texture value type \"{}\" (expected \"float\" or \"spectrum\")",
                                    t.value_type));
            t.type = read_string(f, d, "texture class");
            t.params = with_defaults(read_params(f, true), gs_.texture_attrs);
            t.loc = loc;
            t.world_from_texture = gs_.ctm;
            warn_if_moving(loc, "texture");
            auto& names = t.value_type == "float" ? sc_.float_textures : sc_.spectrum_textures;
            if (auto it = names.find(t.name); it != names.end())
                f.tok.fail(nt, fmt::format("{} texture \"{}\" redefined (first defined at {})", t.value_type,
                                           t.name, sc_.textures[it->second].loc.to_string()));
            names[t.name] = int(sc_.textures.size());
            sc_.textures.push_back(std::move(t));
        }

        // Lights and shapes.
        else if (name == "LightSource") {
            require_world(f, d, true);
            LightDesc l;
            l.type = read_string(f, d, "light type");
            l.params = with_defaults(read_params(f, true), gs_.light_attrs);
            l.loc = loc;
            l.world_from_light = gs_.ctm;
            warn_if_moving(loc, "light");
            l.medium = gs_.outside_medium;
            l.medium_loc = gs_.medium_loc;
            if (instance_)
                f.tok.fail(d,
                           fmt::format("LightSource inside the definition of object \"{}\": lights cannot be "
                                       "instanced",
                                       instance_->name));
            sc_.lights.push_back(std::move(l));
        } else if (name == "AreaLightSource") {
            require_world(f, d, true);
            EntityDesc e;
            e.type = read_string(f, d, "area light type");
            e.params = with_defaults(read_params(f, true), gs_.light_attrs);
            e.loc = loc;
            sc_.area_lights.push_back(std::move(e));
            gs_.area_light = int(sc_.area_lights.size()) - 1;
        } else if (name == "Shape") {
            require_world(f, d, true);
            ShapeDesc s;
            s.type = read_string(f, d, "shape type");
            s.params = with_defaults(read_params(f, true), gs_.shape_attrs);
            s.loc = loc;
            s.world_from_object = gs_.ctm;
            s.motion = motion(loc);
            s.reverse_orientation = gs_.reverse_orientation;
            s.material = gs_.material;
            s.area_light = gs_.area_light;
            s.inside_medium = gs_.inside_medium;
            s.outside_medium = gs_.outside_medium;
            s.medium_loc = gs_.medium_loc;
            if (instance_) {
                if (s.area_light >= 0) {
                    if (!warned_instanced_area_light_) {
                        warned_instanced_area_light_ = true;
                        warn(loc,
                             "area lights are not supported in object instances: the shape does not emit");
                    }
                    s.area_light = -1;
                }
                instance_->shapes.push_back(std::move(s));
            } else {
                sc_.shapes.push_back(std::move(s));
            }
        } else {
            f.tok.fail(d, fmt::format("unknown directive \"{}\"", name));
        }
    }

    // The "string type" parameter of MakeNamedMaterial/MakeNamedMedium; the other parameters go to `rest`.
    std::string take_type(FileFrame& f, const Token& d, const ParamSet& ps, const std::string& n,
                          ParamSet& rest) {
        std::string type;
        bool found = false;
        for (const Param& p : ps.params()) {
            if (p.name == "type") {
                if (p.type != ParamType::String || p.strings.size() != 1)
                    throw Error(p.loc, fmt::format("{} \"{}\": \"type\" must be one string", d.text, n));
                type = p.strings[0];
                found = true;
            } else {
                rest.add(p);
            }
        }
        if (!found) f.tok.fail(d, fmt::format("{} \"{}\": missing parameter \"string type\"", d.text, n));
        return type;
    }

    void pop(FileFrame& f, const Token& d, char kind) {
        if (stack_.empty()) f.tok.fail(d, fmt::format("{} without matching {}", d.text, push_name(kind)));
        PushEntry& top = stack_.back();
        if (top.kind != kind)
            f.tok.fail(d, fmt::format("{} does not match the {} at {}", d.text, push_name(top.kind),
                                      top.loc.to_string()));
        if (kind == 't') {
            gs_.ctm = top.saved.ctm;
            gs_.ctm_end = top.saved.ctm_end;
        } else
            gs_ = std::move(top.saved);
        stack_.pop_back();
    }

    void include(FileFrame& f, const Token& d) {
        Token nt = f.tok.peek();
        std::string name = read_string(f, d, "file name");
        std::string path = resolve_path(f.dir, name);
        if (files_.size() >= size_t(kMaxIncludeDepth))
            f.tok.fail(nt, fmt::format("{}: includes nested more than {} deep", d.text, kMaxIncludeDepth));
        std::string canon = canonical_path(path);
        for (size_t i = 0; i < files_.size(); ++i) {
            if (files_[i]->canonical == canon) {
                std::string chain;
                for (size_t j = i; j < files_.size(); ++j) chain += files_[j]->tok.filename() + " -> ";
                chain += path;
                f.tok.fail(nt, fmt::format("include cycle: {}", chain));
            }
        }
        std::string why;
        auto text = read_text_file(path, why);
        if (!text) f.tok.fail(nt, fmt::format("cannot open included file \"{}\" ({}): {}", name, path, why));
        files_.push_back(std::make_unique<FileFrame>(
            FileFrame{Tokenizer(std::move(*text), path), directory_of(path), canon}));
    }

    void finish() {
        if (!stack_.empty()) {
            const PushEntry& top = stack_.back();
            throw Error(top.loc,
                        fmt::format("{} without matching {} at the end of the scene", push_name(top.kind),
                                    top.kind == 'a'   ? "AttributeEnd"
                                    : top.kind == 't' ? "TransformEnd"
                                                      : "ObjectEnd"));
        }
        for (auto& [n, loc] : named_material_uses_)
            if (!sc_.named_materials.count(n))
                throw Error(loc, fmt::format("NamedMaterial \"{}\": no material of that name is defined", n));
        for (auto& use : sc_.instance_uses)
            if (!sc_.instances.count(use.name))
                throw Error(use.loc, fmt::format("ObjectInstance \"{}\": no object of that name is defined",
                                                 use.name));
    }

    SceneDesc& sc_;
    ParseOptions options_;
    std::vector<std::unique_ptr<FileFrame>> files_;
    GraphicsState gs_;
    std::vector<PushEntry> stack_;
    bool in_world_ = false;
    SourceLocation world_loc_;
    std::map<std::string, std::pair<Transform, Transform>> named_coords_; // start and end transforms
    InstanceDefinition* instance_ = nullptr;
    std::vector<std::pair<std::string, SourceLocation>> named_material_uses_;
    double start_time_ = 0, end_time_ = 1; // TransformTimes
    bool warned_transform_begin_ = false, warned_instanced_area_light_ = false;
};

} // namespace

SceneDesc parse_pbrt_file(const std::string& path, const ParseOptions& options) {
    std::string why;
    auto text = read_text_file(path, why);
    if (!text) throw Error(SourceLocation{path, 0, 0}, "cannot open scene file: " + why);
    SceneDesc sc;
    sc.filename = path;
    sc.base_dir = directory_of(path);
    Parser(sc, options).run(std::move(*text), path, sc.base_dir, canonical_path(path));
    return sc;
}

SceneDesc parse_pbrt_string(const std::string& text, const std::string& virtual_filename,
                            const std::string& base_dir, const ParseOptions& options) {
    SceneDesc sc;
    sc.filename = virtual_filename;
    sc.base_dir = base_dir;
    Parser(sc, options)
        .run(text, virtual_filename, base_dir, canonical_path(resolve_path(base_dir, virtual_filename)));
    return sc;
}

} // namespace illum
