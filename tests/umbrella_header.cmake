# SPDX-License-Identifier: Apache-2.0
# ctest: texsyn/synthesis.h includes every public header (include/texsyn/*.h, and the
# generated version.h), so that a new method's header cannot be left out of it.
# Input: INCLUDE_DIR (core/include).
file(GLOB headers RELATIVE ${INCLUDE_DIR}/texsyn ${INCLUDE_DIR}/texsyn/*.h
     ${INCLUDE_DIR}/texsyn/*.h.in)
file(READ ${INCLUDE_DIR}/texsyn/synthesis.h umbrella)
set(missing "")
foreach(h ${headers})
  string(REGEX REPLACE "\\.in$" "" h "${h}")
  string(FIND "${umbrella}" "#include <texsyn/${h}>" at)
  if(NOT h STREQUAL "synthesis.h" AND at EQUAL -1)
    list(APPEND missing ${h})
  endif()
endforeach()
list(LENGTH headers count)
if(count LESS 10)
  message(FATAL_ERROR "found only ${count} headers in ${INCLUDE_DIR}/texsyn")
endif()
if(missing)
  message(FATAL_ERROR "texsyn/synthesis.h does not include: ${missing}")
endif()
message(STATUS "texsyn/synthesis.h includes the other public headers (${count} in all)")
