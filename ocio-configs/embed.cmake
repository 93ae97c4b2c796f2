# SPDX-License-Identifier: Apache-2.0
# Writes OUTPUT: a C++ file defining texsyn_bundled_ocio_config, the text of INPUT.
file(READ ${INPUT} _text)
set(_delim "texsyn_ocio")
file(WRITE ${OUTPUT} "// Generated from ocio-configs/config.ocio; do not edit.\n"
  "extern const char* const texsyn_bundled_ocio_config;\n"
  "const char* const texsyn_bundled_ocio_config = R\"${_delim}(${_text})${_delim}\";\n")
