#include "illum/image/file_bytes.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "illum/util/error.h"

namespace illum {

namespace {

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

[[noreturn]] void fail(const char* verb, const std::string& path, int err) {
    throw Error(std::string("cannot ") + verb + " " + quoted(path) + ": " + std::strerror(err));
}

// Closes a descriptor on scope exit unless released.
struct Fd {
    int fd = -1;
    ~Fd() {
        if (fd >= 0) ::close(fd);
    }
};

} // namespace

std::vector<unsigned char> read_file_bytes(const std::string& path) {
    Fd f;
    f.fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (f.fd < 0) fail("read", path, errno);
    struct stat st {};
    if (::fstat(f.fd, &st) != 0) fail("read", path, errno);
    if (S_ISDIR(st.st_mode)) fail("read", path, EISDIR);
    std::vector<unsigned char> bytes;
    if (S_ISREG(st.st_mode)) bytes.reserve(std::size_t(st.st_size));
    unsigned char buffer[1 << 16];
    for (;;) {
        const ssize_t n = ::read(f.fd, buffer, sizeof buffer);
        if (n < 0) {
            if (errno == EINTR) continue;
            fail("read", path, errno);
        }
        if (n == 0) break;
        bytes.insert(bytes.end(), buffer, buffer + n);
    }
    return bytes;
}

std::string temporary_path_for(const std::string& path) {
    static std::atomic<unsigned> counter{0};
    const std::size_t slash = path.find_last_of('/');
    const std::string dir = slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
    const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    return dir + "." + name + ".tmp-" + std::to_string(long(::getpid())) + "-" +
           std::to_string(counter.fetch_add(1));
}

void write_file_atomically(const std::string& path, std::string_view bytes) {
    if (path.empty() || path.back() == '/') fail("write", path, EISDIR);
    const std::string tmp = temporary_path_for(path);
    Fd f;
    f.fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (f.fd < 0) fail("write", path, errno);
    // From here on every failure removes the temporary before throwing.
    auto fail_and_remove = [&](int err) {
        if (f.fd >= 0) ::close(f.fd);
        f.fd = -1;
        ::unlink(tmp.c_str());
        fail("write", path, err);
    };
    const char* p = bytes.data();
    std::size_t left = bytes.size();
    while (left > 0) {
        const ssize_t n = ::write(f.fd, p, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            fail_and_remove(errno);
        }
        p += n;
        left -= std::size_t(n);
    }
    // Without the fsync a crash soon after the rename could leave an empty file under the final name.
    if (::fsync(f.fd) != 0) fail_and_remove(errno);
    const int fd = f.fd;
    f.fd = -1;
    if (::close(fd) != 0) fail_and_remove(errno);
    if (std::rename(tmp.c_str(), path.c_str()) != 0) fail_and_remove(errno);
}

} // namespace illum
