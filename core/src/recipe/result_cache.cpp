// SPDX-License-Identifier: Apache-2.0
// The result cache's folder, entries and locks (result_cache_pvt.h; docs/cache.md).
#include "result_cache_pvt.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <mutex>
#include <new>
#include <set>
#include <thread>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

#include <texsyn/io.h>

#include "cache_trust_pvt.h"

namespace texsyn::detail {

namespace {

namespace fs = std::filesystem;

// Attributes of an entry's first part: its key, its number of parts and a fingerprint of
// every part's name, size, channels and pixels. Each part also names its channels in
// order, as OpenEXR stores them sorted by name.
constexpr const char* key_attribute = "synth:cache_key";
constexpr const char* parts_attribute = "synth:cache_parts";
constexpr const char* checksum_attribute = "synth:cache_checksum";
constexpr const char* channels_attribute = "synth:cache_channels";
constexpr const char* mac_attribute = "synth:cache_mac";

// Prints "texsyn WARNING: TEXSYN_CACHE: MESSAGE" once per process and message: every
// process of a farm says so in its own log, and says it once.
void warn_once(const std::string& message)
{
    static std::mutex mutex;
    static std::set<std::string> said;
    std::lock_guard<std::mutex> lock(mutex);
    if (said.insert(message).second)
        std::fprintf(stderr, "texsyn WARNING: TEXSYN_CACHE: %s\n", message.c_str());
}

// Calls `visit` with each part's description (its name, size and channels, a line each)
// and its float pixels, as stored.
void for_each_part(const std::vector<OIIO::ImageBuf>& parts,
    const std::function<void(const std::string&, std::string_view)>& visit)
{
    std::vector<float> pixels;
    for (const OIIO::ImageBuf& part : parts) {
        const OIIO::ImageSpec& spec = part.spec();
        pixels.resize(size_t(spec.image_pixels()) * size_t(spec.nchannels));
        part.get_pixels(part.roi(), OIIO::TypeFloat, pixels.data());
        visit(std::string(spec.get_string_attribute("oiio:subimagename")) + "\n"
                + std::to_string(spec.width) + "x" + std::to_string(spec.height) + "\n"
                + OIIO::Strutil::join(spec.channelnames, ",") + "\n",
            { reinterpret_cast<const char*>(pixels.data()), pixels.size() * sizeof(float) });
    }
}

// Fingerprint of the parts as stored: each one's name, size, channels and float pixels.
// It finds damage; it is no authenticator (anyone can compute it).
std::string entry_checksum(const std::vector<OIIO::ImageBuf>& parts)
{
    std::string text;
    for_each_part(parts, [&](const std::string& description, std::string_view pixels) {
        text += description + fingerprint_hex(pixels) + "\n";
    });
    return fingerprint_hex(text);
}

// HMAC-SHA256 with the site secret of the entry's key and every part as stored: only a
// holder of the secret can make it for a key.
std::string entry_mac(
    const std::string& secret, const std::string& key, const std::vector<OIIO::ImageBuf>& parts)
{
    EntryMac mac(secret);
    mac.update("texsyn cache entry\n" + key + "\n" + std::to_string(parts.size()) + "\n");
    for_each_part(parts, [&](const std::string& description, std::string_view pixels) {
        mac.update(description);
        mac.update(pixels);
    });
    return mac.hex();
}

// Who may have written the cache, and what it needs of an entry to use it.
struct Trust {
    std::string secret;     ///< empty: entries are not authenticated
    struct stat folder { }; ///< the cache folder's status (its owner and mode)
    double lock_timeout = 600.0;
};

// Part `i` of `in`, its channels in the order the entry names them; false with `why`.
bool read_part(
    OIIO::ImageInput& in, int i, const EntryLayout& layout, OIIO::ImageBuf& part, std::string& why)
{
    if (!in.seek_subimage(i, 0)) {
        why = "part " + std::to_string(i) + " is missing";
        return false;
    }
    const OIIO::ImageSpec stored = in.spec();
    const std::vector<std::string> order
        = OIIO::Strutil::splits(stored.get_string_attribute(channels_attribute), "\n");
    std::vector<int> channels;
    for (const std::string& name : order)
        if (stored.channelindex(name) >= 0 && std::count(order.begin(), order.end(), name) == 1)
            channels.push_back(stored.channelindex(name));
    if (channels.size() != order.size() || int(order.size()) != stored.nchannels) {
        why = "part " + std::to_string(i) + " has damaged channel names";
        return false;
    }
    if (i < layout.leading
        && (stored.width != layout.width || stored.height != layout.height
            || order != layout.channelnames)) {
        why = "part " + std::to_string(i) + " has another size or other channels";
        return false;
    }
    OIIO::ImageBuf file_order(
        OIIO::ImageSpec(stored.width, stored.height, stored.nchannels, OIIO::TypeFloat));
    if (!in.read_image(i, 0, 0, stored.nchannels, OIIO::TypeFloat, file_order.localpixels())) {
        why = "part " + std::to_string(i) + " cannot be read ("
            + OIIO::Strutil::replace(in.geterror(), "\n", " ", true) + ")";
        return false;
    }
    if (!OIIO::ImageBufAlgo::channels(
            part, file_order, int(channels.size()), channels, {}, order)) {
        why = part.geterror();
        return false;
    }
    OIIO::ImageSpec named = stored;
    named.channelnames = order;
    part.specmod() = part_spec(named);
    return true;
}

// Why an entry was not used: empty if there is none; `untrusted` if it may be intact but
// its writer is not trusted.
struct EntryProblem {
    std::string why;
    bool untrusted = false;
};

// Reads entry `path` into `images`: true if it is a regular file of a trusted owner that
// holds key `key`, parts of `layout`, the pixels its checksum names and, with a secret,
// their authenticator; false with `problem` otherwise.
bool read_entry(const std::string& path, const std::string& key, const EntryLayout& layout,
    const Trust& trust, std::vector<OIIO::ImageBuf>& images, EntryProblem& problem)
{
    problem = EntryProblem();
    std::string& why = problem.why;
    struct stat st;
    if (::lstat(path.c_str(), &st) != 0)
        return false;
    if (!S_ISREG(st.st_mode)) {
        why = "it is not a regular file";
        return false;
    }
    if (!trusted_owner(st, trust.folder)) {
        problem.untrusted = true;
        why = "it belongs to user " + std::to_string(st.st_uid)
            + ", and anyone may write the folder (only entries of this user, of the folder's "
              "owner and of root are used there)";
        return false;
    }
    auto in = OIIO::ImageInput::open(path);
    if (!in) {
        why = "not an OpenEXR OpenImageIO reads: "
            + OIIO::Strutil::replace(OIIO::geterror(), "\n", " ", true);
        return false;
    }
    const int nparts = in->spec().get_int_attribute(parts_attribute);
    const std::string checksum = in->spec().get_string_attribute(checksum_attribute);
    if (in->spec().get_string_attribute(key_attribute) != key) {
        why = "it holds another key";
        return false;
    }
    if (nparts < layout.leading || (nparts > layout.leading) != layout.more) {
        why = "it holds " + std::to_string(nparts) + " parts";
        return false;
    }
    try {
        std::vector<OIIO::ImageBuf> parts(static_cast<size_t>(nparts));
        for (int i = 0; i < nparts; ++i)
            if (!read_part(*in, i, layout, parts[size_t(i)], why))
                return false;
        if (entry_checksum(parts) != checksum) {
            why = "its pixels do not match its checksum";
            return false;
        }
        if (!trust.secret.empty()
            && !same_mac(entry_mac(trust.secret, key, parts),
                in->spec().get_string_attribute(mac_attribute))) {
            problem.untrusted = true;
            why = "it is not authenticated with $TEXSYN_CACHE_SECRET (written without it, or "
                  "forged)";
            return false;
        }
        images = std::move(parts);
        return true;
    } catch (const std::bad_alloc&) { // a damaged header may claim any size
        why = "its parts are too large";
        return false;
    }
}

// Stores `images` as entry `path` (atomically: temporary file + rename).
bool write_entry(const std::string& path, const std::string& key, const Trust& trust,
    const std::vector<OIIO::ImageBuf>& images, std::string& error)
{
    std::vector<OIIO::ImageSpec> specs;
    for (const OIIO::ImageBuf& image : images) {
        specs.push_back(part_spec(image.spec()));
        specs.back().attribute(
            channels_attribute, OIIO::Strutil::join(image.spec().channelnames, "\n"));
    }
    specs[0].attribute(key_attribute, key);
    specs[0].attribute(parts_attribute, int(images.size()));
    specs[0].attribute(checksum_attribute, entry_checksum(images));
    if (!trust.secret.empty())
        specs[0].attribute(mac_attribute, entry_mac(trust.secret, key, images));
    return write_multipart_exr(
        path, specs, [&](size_t i, OIIO::ImageBuf& buf) { buf.copy(images[i]); }, error);
}

// An exclusive flock() on a lock file while it lives (released by closing, and by the
// kernel if the process dies), waited for at most the trust's lock timeout.
class EntryLock {
public:
    EntryLock(const std::string& path, const Trust& trust)
    {
        // Never through a planted link (O_NOFOLLOW), and only a regular file of an owner
        // the folder trusts: a FIFO or device at the lock's name is not used, nor a lock
        // another user of a world-writable folder planted to hold.
        m_fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK, 0666);
        struct stat st;
        if (m_fd >= 0 && (::fstat(m_fd, &st) != 0 || !S_ISREG(st.st_mode))) {
            release();
            m_why = path + ": cannot lock (not a regular file)";
            return;
        }
        if (m_fd >= 0 && !trusted_owner(st, trust.folder)) {
            release();
            m_why = path + ": not used (it belongs to user " + std::to_string(st.st_uid)
                + ", and anyone may write the folder)";
            return;
        }
        if (m_fd < 0) {
            m_why = path + ": cannot lock (" + std::strerror(errno) + ")";
            return;
        }
        // Polled, so that a holder that is stopped or hung delays others by the timeout
        // at most.
        const auto deadline
            = std::chrono::steady_clock::now() + std::chrono::duration<double>(trust.lock_timeout);
        while (::flock(m_fd, LOCK_EX | LOCK_NB) != 0) {
            if (errno != EWOULDBLOCK && errno != EINTR) {
                m_why = path + ": cannot lock (" + std::strerror(errno) + ")";
                release();
                return;
            }
            if (std::chrono::steady_clock::now() >= deadline) {
                m_why = path + ": still held by another process after "
                    + OIIO::Strutil::fmt::format("{:g}", trust.lock_timeout)
                    + " s ($TEXSYN_CACHE_LOCK_TIMEOUT): synthesizing without waiting more";
                release();
                return;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
    }
    ~EntryLock() { release(); }
    EntryLock(const EntryLock&) = delete;
    EntryLock& operator=(const EntryLock&) = delete;

    /// Empty if the lock is held, else why not.
    const std::string& why() const { return m_why; }

private:
    void release()
    {
        if (m_fd >= 0)
            ::close(m_fd);
        m_fd = -1;
    }

    int m_fd = -1;
    std::string m_why;
};

// The trust settings of cache folder `folder`; false (warned) if they are unusable.
bool cache_trust(const std::string& folder, Trust& trust)
{
    std::string why;
    if (!cache_secret(trust.secret, why)) {
        warn_once(why + "; synthesizing without the cache");
        return false;
    }
    if (::stat(folder.c_str(), &trust.folder) != 0) {
        warn_once(folder + ": " + std::strerror(errno) + "; synthesizing without the cache");
        return false;
    }
    if (!lock_timeout_seconds(trust.lock_timeout, why))
        warn_once(why + "; waiting 600 s");
    return true;
}

} // namespace

bool result_cache_folder(std::string& folder, bool& writable)
{
    const char* env = std::getenv("TEXSYN_CACHE");
    if (!env || !*env)
        return false;
    folder = env;
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (!fs::is_directory(folder, ec)) {
        warn_once(folder + ": cannot create the folder"
            + (ec ? " (" + ec.message() + ")" : std::string(" (a file has that name)"))
            + "; synthesizing without the cache");
        return false;
    }
    writable = ::access(folder.c_str(), W_OK | X_OK) == 0;
    if (!writable)
        warn_once(folder + ": the folder is not writable: results are read from it, not stored");
    return true;
}

OIIO::ImageSpec part_spec(const OIIO::ImageSpec& src)
{
    OIIO::ImageSpec spec(src.width, src.height, src.nchannels, OIIO::TypeFloat);
    spec.channelnames = src.channelnames;
    spec.alpha_channel = -1;
    for (int c = 0; c < src.nchannels; ++c)
        if (OIIO::Strutil::iequals(spec.channelnames[size_t(c)], "A")
            || OIIO::Strutil::iequals(spec.channelnames[size_t(c)], "Alpha"))
            spec.alpha_channel = c;
    spec.full_width = src.full_width;
    spec.full_height = src.full_height;
    spec.attribute("oiio:subimagename", src.get_string_attribute("oiio:subimagename"));
    for (const OIIO::ParamValue& p : src.extra_attribs)
        if (OIIO::Strutil::starts_with(p.name(), "synth:")
            && !OIIO::Strutil::starts_with(p.name(), "synth:cache_"))
            spec.attribute(p.name(), p.type(), p.data());
    return spec;
}

bool cached_images(const std::string& folder, bool writable, const std::string& key,
    const EntryLayout& layout, const std::string& label,
    const std::function<bool(std::vector<OIIO::ImageBuf>&, std::string&)>& make,
    std::vector<OIIO::ImageBuf>& images, std::string& error)
{
    Trust trust;
    if (!cache_trust(folder, trust))
        return make(images, error);
    const std::string path = (fs::path(folder) / (key + ".exr")).string();
    EntryProblem problem;
    if (read_entry(path, key, layout, trust, images, problem)) {
        cache_note("hit " + key + " (" + label + ")");
        return true;
    }
    // Entries appear by rename, so an unlocked read sees a whole one or none; the lock is
    // for making one. Whoever held it may have stored the entry meanwhile: read again.
    std::unique_ptr<EntryLock> lock;
    if (writable) {
        lock = std::make_unique<EntryLock>((fs::path(folder) / (key + ".lock")).string(), trust);
        if (!lock->why().empty())
            warn_once(lock->why() + ": processes may synthesize the same result at once");
        else if (read_entry(path, key, layout, trust, images, problem)) {
            cache_note("hit " + key + " after waiting (" + label + ")");
            return true;
        }
    }
    if (!problem.why.empty())
        warn_once(path + ": ignoring " + (problem.untrusted ? "an untrusted" : "a damaged")
            + " entry (" + problem.why + "); it is made again");
    cache_note("miss " + key + ", synthesizing (" + label + ")");
    if (!make(images, error))
        return false;
    if (!writable)
        return true;
    std::string reason;
    if (!write_entry(path, key, trust, images, reason))
        warn_once(reason);
    else
        cache_note("stored " + key);
    return true;
}

void cache_note(const std::string& line)
{
    const char* env = std::getenv("TEXSYN_CACHE_VERBOSE");
    if (env && *env && std::strcmp(env, "0") != 0)
        std::fprintf(stderr, "texsyn cache: %s\n", line.c_str());
}

} // namespace texsyn::detail
