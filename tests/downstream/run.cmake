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
foreach(f bin/texsyn include/texsyn/synthesis.h include/texsyn/version.h
          lib/pkgconfig/texsyn.pc share/texsyn/ocio/config.ocio
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
# The same program built with pkg-config alone (no CMake), as other build systems would.
execute_process(COMMAND ${CMAKE_COMMAND} -E env PKG_CONFIG_PATH=${WORK_DIR}/prefix/lib/pkgconfig
                        pkg-config --cflags --libs texsyn
                RESULT_VARIABLE rc OUTPUT_VARIABLE flags OUTPUT_STRIP_TRAILING_WHITESPACE)
if(rc OR NOT flags MATCHES "-ltexsyn")
  message(FATAL_ERROR "pkg-config --cflags --libs texsyn failed: ${rc} ${flags}")
endif()
separate_arguments(flags UNIX_COMMAND "${flags}")
execute_process(COMMAND c++ -std=c++17 ${SOURCE_DIR}/main.cpp ${flags}
                        -Wl,-rpath,${WORK_DIR}/prefix/lib -o ${WORK_DIR}/downstream_pc
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "building with pkg-config's flags failed: ${rc} ${err}")
endif()
execute_process(COMMAND ${WORK_DIR}/downstream_pc RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(rc OR NOT out MATCHES "texsyn [0-9]+\\.[0-9]+\\.[0-9]+ ")
  message(FATAL_ERROR "the pkg-config-built program failed: ${rc} ${out}")
endif()
# The installed library's SONAME names major.minor while the version is 0.x.
execute_process(COMMAND readelf -d ${WORK_DIR}/prefix/lib/libtexsyn.so OUTPUT_VARIABLE dynamic)
if(NOT dynamic MATCHES "Library soname: \\[libtexsyn\\.so\\.0\\.[0-9]+\\]")
  message(FATAL_ERROR "libtexsyn's SONAME is not libtexsyn.so.0.MINOR: ${dynamic}")
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
