# SPDX-License-Identifier: Apache-2.0
# Fails if DOC differs from what `GEN ARG` prints now.
execute_process(COMMAND ${GEN} ${ARG} OUTPUT_FILE ${OUT} RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "${GEN} failed: ${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${DOC} ${OUT} RESULT_VARIABLE diff)
if(diff)
  message(FATAL_ERROR "${DOC} is stale: run `cmake --build build --target docs`")
endif()
