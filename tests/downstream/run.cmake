# SPDX-License-Identifier: Apache-2.0
# ctest driver: installs the built texsyn into a scratch prefix, then configures, builds
# and runs tests/downstream against that prefix only.
# Inputs: BUILD_DIR, SOURCE_DIR, WORK_DIR; PYTHON_SITEDIR (where the Python package is
# installed in the prefix, if it is built).
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "install failed: ${rc}")
endif()
foreach(f bin/texsyn include/texsyn/synthesis.h share/texsyn/ocio/config.ocio
          lib/cmake/texsyn/texsynConfig.cmake lib/texsyn/plugins/texsyn.imageio.so)
  if(NOT EXISTS ${WORK_DIR}/prefix/${f})
    message(FATAL_ERROR "install is missing ${f}")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/build
                        -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_BUILD_TYPE=Release
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "configuring the downstream project failed: ${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building the downstream project failed: ${rc}")
endif()
execute_process(COMMAND ${WORK_DIR}/build/downstream RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "the downstream program failed: ${rc}")
endif()
execute_process(COMMAND ${WORK_DIR}/prefix/bin/texsyn --version RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "the installed texsyn does not run: ${rc}")
endif()
# The installed plugin, found through OIIO_LIBRARY_PATH as docs/recipes.md says.
configure_file(${SOURCE_DIR}/../../data/samples/stucco_yellow.png ${WORK_DIR}/s.png COPYONLY)
execute_process(COMMAND ${CMAKE_COMMAND} -E env OCIO= OIIO_LIBRARY_PATH=${WORK_DIR}/prefix/lib/texsyn/plugins
                        iinfo "${WORK_DIR}/s.png.texsyn?size=32x32&iterations=1"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(rc OR NOT out MATCHES "32 x   32, 3 channel, float texsyn")
  message(FATAL_ERROR "the installed plugin does not open a recipe: ${rc} ${out}")
endif()
# The installed Python package, imported from the prefix only (docs/python.md).
if(PYTHON_SITEDIR)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env OCIO= PYTHONPATH=${WORK_DIR}/prefix/${PYTHON_SITEDIR}
                          /usr/bin/python3 -c
                          "import texsyn; assert texsyn.__file__.startswith('${WORK_DIR}/prefix/'), texsyn.__file__; a = texsyn.cascade(size=(16, 16)); print(a.shape, a.dtype)"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc OR NOT out MATCHES "\\(16, 16, 1\\) float32")
    message(FATAL_ERROR "the installed Python package does not work: ${rc} ${out} ${err}")
  endif()
endif()
