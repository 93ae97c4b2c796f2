// SPDX-License-Identifier: Apache-2.0
// Whom a shared result cache trusts (docs/cache.md, "Who can write the cache"): the site
// secret that authenticates entries, the owners whose entries and locks are used, and how
// long a process waits for another's lock.
#pragma once

#include <string>
#include <string_view>

#include <sys/stat.h>

namespace texsyn::detail {

/// The site secret $TEXSYN_CACHE_SECRET names: true with it in `secret`, or with `secret`
/// empty if the variable is unset or empty. False (with `why`) if the file is not a
/// regular file, cannot be read, or holds fewer than 16 or more than 4096 bytes.
bool cache_secret(std::string& secret, std::string& why);

/// Incremental HMAC-SHA256 with a secret (OpenSSL).
class EntryMac {
public:
    explicit EntryMac(const std::string& secret);
    ~EntryMac();
    EntryMac(const EntryMac&) = delete;
    EntryMac& operator=(const EntryMac&) = delete;

    void update(std::string_view bytes);
    /// 64 hex digits; empty if OpenSSL failed.
    std::string hex();

private:
    struct State;
    State* m_state;
};

/// Whether two authenticators are equal, in time that does not depend on where they differ.
bool same_mac(const std::string& a, const std::string& b);

/// Whether a file with status `file` in the cache folder with status `folder` may be used:
/// the folder's writers are whom a cache trusts. Any file if no one but its owner and
/// group may write the folder; in a folder anyone may write (o+w, like /tmp), only files of
/// this process's user, of the folder's owner and of root.
bool trusted_owner(const struct stat& file, const struct stat& folder);

/// Seconds a process waits for another process's lock on an entry before it synthesizes
/// the result itself: $TEXSYN_CACHE_LOCK_TIMEOUT (0 to 86400), else 600. False (with
/// `why`) for another value.
bool lock_timeout_seconds(double& seconds, std::string& why);

} // namespace texsyn::detail
