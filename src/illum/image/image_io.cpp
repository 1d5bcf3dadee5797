#include "illum/image/image_io.h"

#include <cctype>

#include "illum/image/exr.h"
#include "illum/image/file_bytes.h"
#include "illum/image/hdr.h"
#include "illum/image/ldr.h"
#include "illum/image/pfm.h"
#include "illum/util/error.h"

namespace illum {

namespace {

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

bool is_ldr_input(const std::string& ext) {
    return ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".tga" || ext == ".bmp";
}

[[noreturn]] void unknown_extension(const std::string& path, const std::string& ext, const char* list) {
    if (ext.empty()) throw Error(quoted(path) + " has no image extension (use " + list + ")");
    throw Error("unknown image extension " + quoted(ext) + " (use " + list + ")");
}

constexpr const char* kOutputList = ".exr, .pfm, .hdr or .png";
constexpr const char* kInputList = ".exr, .pfm, .hdr, .png, .jpg, .tga or .bmp";

} // namespace

std::string image_extension(const std::string& path) {
    const std::size_t slash = path.find_last_of('/');
    const std::size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
    // A leading dot names a hidden file, not an extension (".exr" alone has none).
    if (dot == (slash == std::string::npos ? 0 : slash + 1)) return {};
    std::string ext = path.substr(dot);
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

bool is_supported_output_extension(const std::string& path) {
    const std::string ext = image_extension(path);
    return ext == ".exr" || ext == ".pfm" || ext == ".hdr" || ext == ".png";
}

bool is_supported_input_extension(const std::string& path) {
    const std::string ext = image_extension(path);
    return ext == ".exr" || ext == ".pfm" || ext == ".hdr" || is_ldr_input(ext);
}

Image read_image(const std::string& path) {
    const std::string ext = image_extension(path);
    if (!is_supported_input_extension(path)) unknown_extension(path, ext, kInputList);
    const std::vector<unsigned char> bytes = read_file_bytes(path);
    if (ext == ".exr") return decode_exr(bytes, path);
    if (ext == ".pfm") return decode_pfm(bytes, path);
    if (ext == ".hdr") return decode_hdr(bytes, path);
    return decode_ldr(bytes, path);
}

void write_image(const Image& image, const std::string& path, const WriteOptions& opts) {
    const std::string ext = image_extension(path);
    if (!is_supported_output_extension(path)) unknown_extension(path, ext, kOutputList);
    if (image.empty())
        throw Error("cannot write " + quoted(path) + ": the image is empty (" +
                    std::to_string(image.width()) + "x" + std::to_string(image.height()) + ")");
    std::string bytes;
    try {
        if (ext == ".exr")
            bytes = encode_exr(image, opts.exr);
        else if (ext == ".pfm")
            bytes = encode_pfm(image);
        else if (ext == ".hdr")
            bytes = encode_hdr(image);
        else
            bytes = encode_png(image, opts.tonemap, opts.exposure_stops);
    } catch (const Error& e) {
        throw Error("cannot write " + quoted(path) + ": " + e.message());
    }
    write_file_atomically(path, bytes);
}

} // namespace illum
