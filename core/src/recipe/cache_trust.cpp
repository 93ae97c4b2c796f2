// SPDX-License-Identifier: Apache-2.0
// The result cache's trust model (cache_trust_pvt.h): entries authenticated with a site
// secret, owners the folder trusts, a bounded wait for locks.
#include "cache_trust_pvt.h"

#include <charconv>
#include <cstdlib>
#include <fstream>
#include <iterator>

#include <openssl/core_names.h>
#include <openssl/crypto.h>
#include <openssl/evp.h>
#include <unistd.h>

#include <texsyn/io.h>

namespace texsyn::detail {

bool cache_secret(std::string& secret, std::string& why)
{
    secret.clear();
    const char* env = std::getenv("TEXSYN_CACHE_SECRET");
    if (!env || !*env)
        return true;
    if (!check_regular_file(env, "a secret", why))
        return false;
    std::ifstream in(env, std::ios::binary);
    std::string bytes;
    char buffer[4097];
    in.read(buffer, sizeof(buffer));
    bytes.assign(buffer, size_t(in.gcount()));
    if (!in.eof() && !in) {
        why = std::string(env) + ": cannot be read";
        return false;
    }
    if (bytes.size() < 16 || bytes.size() > 4096) {
        why = std::string(env)
            + ": a cache secret is 16 to 4096 bytes (e.g. head -c 32 "
              "/dev/urandom | base64 > FILE)";
        return false;
    }
    secret = std::move(bytes);
    return true;
}

struct EntryMac::State {
    EVP_MAC* mac = nullptr;
    EVP_MAC_CTX* ctx = nullptr;
    bool ok = false;
};

EntryMac::EntryMac(const std::string& secret)
    : m_state(new State)
{
    m_state->mac = EVP_MAC_fetch(nullptr, "HMAC", nullptr);
    m_state->ctx = m_state->mac ? EVP_MAC_CTX_new(m_state->mac) : nullptr;
    char digest[] = "SHA256";
    const OSSL_PARAM params[]
        = { OSSL_PARAM_construct_utf8_string(OSSL_MAC_PARAM_DIGEST, digest, 0),
              OSSL_PARAM_construct_end() };
    m_state->ok = m_state->ctx
        && EVP_MAC_init(m_state->ctx, reinterpret_cast<const unsigned char*>(secret.data()),
               secret.size(), params)
            == 1;
}

EntryMac::~EntryMac()
{
    EVP_MAC_CTX_free(m_state->ctx);
    EVP_MAC_free(m_state->mac);
    delete m_state;
}

void EntryMac::update(std::string_view bytes)
{
    if (m_state->ok)
        m_state->ok = EVP_MAC_update(m_state->ctx,
                          reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size())
            == 1;
}

std::string EntryMac::hex()
{
    unsigned char out[EVP_MAX_MD_SIZE];
    size_t size = 0;
    if (!m_state->ok || EVP_MAC_final(m_state->ctx, out, &size, sizeof(out)) != 1)
        return {};
    static const char digits[] = "0123456789abcdef";
    std::string text;
    for (size_t i = 0; i < size; ++i) {
        text += digits[out[i] >> 4];
        text += digits[out[i] & 15];
    }
    return text;
}

bool same_mac(const std::string& a, const std::string& b)
{
    return a.size() == b.size() && !a.empty() && CRYPTO_memcmp(a.data(), b.data(), a.size()) == 0;
}

bool trusted_owner(const struct stat& file, const struct stat& folder)
{
    if (!(folder.st_mode & S_IWOTH))
        return true;
    return file.st_uid == ::geteuid() || file.st_uid == folder.st_uid || file.st_uid == 0;
}

bool lock_timeout_seconds(double& seconds, std::string& why)
{
    seconds = 600.0;
    const char* env = std::getenv("TEXSYN_CACHE_LOCK_TIMEOUT");
    if (!env || !*env)
        return true;
    const std::string_view text(env);
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), seconds);
    if (ec != std::errc() || end != text.data() + text.size() || !(seconds >= 0.0)
        || seconds > 86400.0) {
        why = "TEXSYN_CACHE_LOCK_TIMEOUT=" + std::string(text.substr(0, 40))
            + ": expected seconds from 0 to 86400";
        seconds = 600.0;
        return false;
    }
    return true;
}

} // namespace texsyn::detail
