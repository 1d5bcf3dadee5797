// A well-formedness check of XML 1.0 for the SVG tests, written for them: one root element, every tag
// closed in order, attributes name="value" or name='value' without duplicates and without a raw '<' or
// '&' that is not an entity, text without a raw '<' and with only known entities (the five predefined
// ones and numeric character references), comments, and a prolog (<?xml ...?>) only at the very
// start. It does not validate against the SVG schema; it answers "does an XML parser accept this".
#pragma once

#include <cctype>
#include <set>
#include <string>
#include <vector>

namespace illum::test {

struct XmlCheck {
    bool ok = true;
    std::string error;                 // the first problem, with its byte offset
    std::string root;                  // the root element's name
    std::vector<std::string> elements; // every element's name, in document order
};

namespace xml_detail {

inline bool name_start(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == ':' ||
           (static_cast<unsigned char>(c) >= 0x80);
}
inline bool name_char(char c) {
    return name_start(c) || std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '.';
}

// An entity or character reference at s[i] == '&'; returns its length or 0 when invalid.
inline std::size_t reference(const std::string& s, std::size_t i) {
    std::size_t end = s.find(';', i);
    if (end == std::string::npos || end - i > 12) return 0;
    std::string body = s.substr(i + 1, end - i - 1);
    static const std::set<std::string> known = {"amp", "lt", "gt", "quot", "apos"};
    if (known.count(body)) return end - i + 1;
    if (body.size() >= 2 && body[0] == '#') {
        bool hex = body[1] == 'x';
        for (std::size_t k = hex ? 2 : 1; k < body.size(); ++k)
            if (!(hex ? std::isxdigit(static_cast<unsigned char>(body[k]))
                      : std::isdigit(static_cast<unsigned char>(body[k]))))
                return 0;
        return body.size() > (hex ? 2u : 1u) ? end - i + 1 : 0;
    }
    return 0;
}

} // namespace xml_detail

inline XmlCheck check_xml(const std::string& s) {
    using namespace xml_detail;
    XmlCheck r;
    auto fail = [&](std::size_t at, const std::string& what) {
        if (r.ok) r.error = what + " at byte " + std::to_string(at);
        r.ok = false;
    };
    std::vector<std::string> open;
    std::size_t i = 0;
    bool seen_root = false;
    if (s.compare(0, 5, "<?xml") == 0) {
        std::size_t end = s.find("?>");
        if (end == std::string::npos) return fail(0, "unterminated prolog"), r;
        i = end + 2;
    }
    while (i < s.size() && r.ok) {
        if (s[i] != '<') {
            if (s[i] == '&') {
                std::size_t n = reference(s, i);
                if (!n) fail(i, "bad entity reference");
                i += n ? n : 1;
                continue;
            }
            if (open.empty() && !std::isspace(static_cast<unsigned char>(s[i])))
                fail(i, "text outside the root element");
            ++i;
            continue;
        }
        if (s.compare(i, 4, "<!--") == 0) {
            std::size_t end = s.find("-->", i + 4);
            if (end == std::string::npos) fail(i, "unterminated comment");
            i = end + 3;
            continue;
        }
        if (s.compare(i, 2, "<?") == 0) {
            fail(i, "processing instruction after the start");
            break;
        }
        bool closing = s.compare(i, 2, "</") == 0;
        std::size_t j = i + (closing ? 2 : 1);
        if (j >= s.size() || !name_start(s[j])) {
            fail(i, "bad tag name");
            break;
        }
        std::size_t name_begin = j;
        while (j < s.size() && name_char(s[j])) ++j;
        std::string name = s.substr(name_begin, j - name_begin);
        if (closing) {
            while (j < s.size() && std::isspace(static_cast<unsigned char>(s[j]))) ++j;
            if (j >= s.size() || s[j] != '>') {
                fail(j, "bad closing tag");
                break;
            }
            if (open.empty() || open.back() != name) {
                fail(i, "closing </" + name + "> does not match <" + (open.empty() ? "" : open.back()) + ">");
                break;
            }
            open.pop_back();
            i = j + 1;
            continue;
        }
        if (open.empty()) {
            if (seen_root) {
                fail(i, "a second root element <" + name + ">");
                break;
            }
            seen_root = true;
            r.root = name;
        }
        r.elements.push_back(name);
        std::set<std::string> attributes;
        bool self_closing = false;
        while (true) {
            std::size_t before = j;
            while (j < s.size() && std::isspace(static_cast<unsigned char>(s[j]))) ++j;
            if (j >= s.size()) {
                fail(i, "unterminated tag <" + name + ">");
                break;
            }
            if (s[j] == '>') {
                ++j;
                break;
            }
            if (s.compare(j, 2, "/>") == 0) {
                self_closing = true;
                j += 2;
                break;
            }
            if (j == before || !name_start(s[j])) {
                fail(j, "bad attribute in <" + name + ">");
                break;
            }
            std::size_t a0 = j;
            while (j < s.size() && name_char(s[j])) ++j;
            std::string attr = s.substr(a0, j - a0);
            if (!attributes.insert(attr).second) fail(a0, "duplicate attribute " + attr);
            while (j < s.size() && std::isspace(static_cast<unsigned char>(s[j]))) ++j;
            if (j >= s.size() || s[j] != '=') {
                fail(j, "attribute " + attr + " without a value");
                break;
            }
            ++j;
            while (j < s.size() && std::isspace(static_cast<unsigned char>(s[j]))) ++j;
            if (j >= s.size() || (s[j] != '"' && s[j] != '\'')) {
                fail(j, "unquoted attribute " + attr);
                break;
            }
            char q = s[j++];
            while (j < s.size() && s[j] != q) {
                if (s[j] == '<') fail(j, "'<' in attribute " + attr);
                if (s[j] == '&') {
                    std::size_t n = reference(s, j);
                    if (!n) fail(j, "bad entity in attribute " + attr);
                    j += n ? n : 1;
                    continue;
                }
                ++j;
            }
            if (j >= s.size()) {
                fail(a0, "unterminated attribute " + attr);
                break;
            }
            ++j;
        }
        if (!r.ok) break;
        if (!self_closing) open.push_back(name);
        i = j;
    }
    if (r.ok && !open.empty()) fail(s.size(), "<" + open.back() + "> is never closed");
    if (r.ok && !seen_root) fail(0, "no root element");
    return r;
}

} // namespace illum::test
