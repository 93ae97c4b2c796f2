// SPDX-License-Identifier: Apache-2.0
// Temporary output files: created exclusively (never through a planted link), named so
// that their owner (host and pid) is recognisable, registered while they exist so that a
// signal handler or an exit() deep inside an image library can remove them, and committed
// by rename over a destination that is a regular file, a link (replaced itself) or nothing.
#include <texsyn/io.h>

#include <algorithm>
#include <atomic>
#include <climits>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <random>
#include <set>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace texsyn {

namespace fs = std::filesystem;

namespace {

constexpr const char* marker = ".texsyn-tmp";

// The live temporaries, readable from a signal handler: fixed slots, no allocation.
struct Slot {
    std::atomic<int> state { 0 }; // 0 free, 1 being filled, 2 live
    char path[PATH_MAX];
};
constexpr int nslots = 64;
Slot slots[nslots];

void register_live(const std::string& path)
{
    if (path.size() >= PATH_MAX)
        return;
    for (Slot& s : slots) {
        int expected = 0;
        if (s.state.compare_exchange_strong(expected, 1)) {
            std::memcpy(s.path, path.c_str(), path.size() + 1);
            s.state.store(2, std::memory_order_release);
            return;
        }
    }
}

void unregister_live(const std::string& path)
{
    for (Slot& s : slots) {
        if (s.state.load(std::memory_order_acquire) == 2 && path == s.path) {
            s.state.store(0, std::memory_order_release);
            return;
        }
    }
}

// Eight hex digits naming this host, so that a folder shared between machines never sees
// one host remove another's live temporary.
const std::string& host_tag()
{
    static const std::string tag = [] {
        char name[256] = {};
        ::gethostname(name, sizeof(name) - 1);
        uint32_t h = 2166136261u; // FNV-1a 32
        for (const char* p = name; *p; ++p)
            h = (h ^ uint8_t(*p)) * 16777619u;
        char buf[9];
        std::snprintf(buf, sizeof(buf), "%08x", h);
        return std::string(buf);
    }();
    return tag;
}

// The pid in a temporary name of this host (".STEM.texsyn-tmpPID-HOST-N.EXT"), or 0.
long stale_owner(const std::string& name)
{
    if (name.empty() || name[0] != '.')
        return 0;
    const size_t at = name.rfind(marker);
    if (at == std::string::npos)
        return 0;
    const char* p = name.c_str() + at + std::strlen(marker);
    char* end = nullptr;
    const long pid = std::strtol(p, &end, 10);
    if (pid <= 0 || *end != '-' || std::strncmp(end + 1, host_tag().c_str(), 8) != 0
        || end[9] != '-')
        return 0;
    return pid;
}

// Removes, once per folder and process, the temporaries that processes of this host left
// behind when they died without cleaning up (SIGKILL, power loss).
void remove_stale_temporaries(const fs::path& folder)
{
    static std::mutex mutex;
    static std::set<std::string> visited;
    std::error_code ec;
    const std::string key = fs::absolute(folder.empty() ? fs::path(".") : folder, ec).string();
    {
        std::lock_guard<std::mutex> lock(mutex);
        if (!visited.insert(key).second)
            return;
    }
    for (fs::directory_iterator it(key, ec), end; !ec && it != end; it.increment(ec)) {
        const long pid = stale_owner(it->path().filename().string());
        if (pid > 0 && pid != long(::getpid()) && ::kill(pid_t(pid), 0) != 0 && errno == ESRCH
            && it->is_regular_file(ec)) {
            std::error_code ignored;
            fs::remove(it->path(), ignored);
        }
    }
}

} // namespace

std::string temporary_path_for(const std::string& filename)
{
    static std::atomic<unsigned> counter { 0 };
    fs::path p(filename);
    remove_stale_temporaries(p.parent_path());
    std::random_device entropy;
    std::string path;
    for (int attempt = 0; attempt < 64; ++attempt) {
        // Within NAME_MAX (255) even for a long name: the stem is shortened, never the
        // marker, owner and extension that make the file recognisable. The random part
        // makes the name unpredictable to anyone who could plant a link there in advance.
        char unique[32];
        std::snprintf(unique, sizeof(unique), "%u-%08x", counter++, unsigned(entropy()));
        const std::string tag = marker + std::to_string(::getpid()) + "-" + host_tag() + "-"
            + unique + p.extension().string();
        std::string stem = p.stem().string();
        if (1 + stem.size() + tag.size() > 255)
            stem.resize(255 - 1 - std::min<size_t>(tag.size(), 254));
        path = (p.parent_path() / ("." + stem + tag)).string();
        // Created here, exclusively and not through a link, so that the writer opens a
        // regular file of ours; a name someone else made is skipped, never followed. It is
        // registered first: a signal that arrives as the file appears still finds it (the
        // name, with this process's pid and a random part, can be no one else's file).
        std::error_code ec;
        const std::string absolute = fs::absolute(path, ec).string();
        register_live(absolute);
        const int fd
            = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (fd >= 0) {
            ::close(fd);
            return path;
        }
        const int why = errno;
        unregister_live(absolute);
        if (why != EEXIST)
            return path; // the folder refuses files: so will the writer, with its reason
    }
    return path + "/"; // 64 names taken: a path no writer can create
}

void discard_temporary(const std::string& temporary)
{
    std::error_code ec;
    fs::remove(temporary, ec);
    unregister_live(fs::absolute(temporary, ec).string());
}

bool check_output_destination(const std::string& filename, std::string& error)
{
    struct stat st;
    if (::lstat(filename.c_str(), &st) != 0 || S_ISREG(st.st_mode) || S_ISLNK(st.st_mode))
        return true;
    error = filename + ": exists and is not a regular file ("
        + (S_ISDIR(st.st_mode) ? "a directory" : "a device, FIFO or socket")
        + "); texsyn does not replace it";
    return false;
}

bool commit_file(const std::string& temporary, const std::string& filename, std::string& error)
{
    // The temporary must still be the regular file this process made: in a folder others
    // can write, a name swapped for a link or another user's file is not renamed into place.
    struct stat st;
    if (::lstat(temporary.c_str(), &st) != 0 || !S_ISREG(st.st_mode) || st.st_uid != ::geteuid()
        || st.st_nlink != 1) {
        discard_temporary(temporary);
        error = filename
            + ": cannot write (its temporary file was replaced while it was "
              "written: is someone else writing to this folder?)";
        return false;
    }
    if (!check_output_destination(filename, error)) {
        discard_temporary(temporary);
        return false;
    }
    std::error_code ec;
    fs::rename(temporary, filename, ec);
    if (ec) {
        discard_temporary(temporary);
        error = filename + ": cannot write (" + ec.message() + ")";
        return false;
    }
    unregister_live(fs::absolute(temporary, ec).string());
    return true;
}

void remove_live_temporaries() noexcept
{
    for (Slot& s : slots)
        if (s.state.load(std::memory_order_acquire) == 2)
            ::unlink(s.path);
}

} // namespace texsyn
