// SPDX-License-Identifier: Apache-2.0
// TEXSYN_API: what libtexsyn exports. The library is compiled with hidden visibility (as
// OpenImageIO and libvips are); every public header opens its namespace as
// `namespace TEXSYN_API texsyn {`, so what the public headers declare is exported and
// nothing else is: the library's internals (src/**/*_pvt.h) are not part of its ABI.
#pragma once

#if defined(__GNUC__) || defined(__clang__)
#define TEXSYN_API [[gnu::visibility("default")]]
#else
#define TEXSYN_API
#endif
