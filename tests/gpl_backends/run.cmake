# SPDX-License-Identifier: Apache-2.0
# ctest driver: builds texsyn with the optional GPL backends (FFTW, CGAL's remesher) in a
# scratch tree and runs the tests that compare them with the permissive defaults: FFT and
# pyramid tests (FFTW with KissFFT), surface mesh tests (CGAL's remesher with texsyn's own),
# and checks that its `texsyn --version` names the GPL backends.
# The default build (the one the rest of the suite tests) has no GPL code, so this is the
# only place these backends are exercised. Inputs: SOURCE_DIR, WORK_DIR.
# It compiles the library a second time, the largest item of the suite: at -O1, since the
# comparisons are of results, not speed (the library's sources take 137 s of CPU at -O1
# against 186 s at Release's -O3), and without the Python module and benchmarks.
set(tests fft_test pyramid_test surface_mesh_test)
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}
                        -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG"
                        -DTEXSYN_WITH_FFTW=ON -DTEXSYN_WITH_CGAL=ON
                        -DTEXSYN_BUILD_BENCH=OFF -DTEXSYN_BUILD_PYTHON=OFF
                OUTPUT_QUIET RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "configuring the GPL backends build failed: ${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR} -j2 --target ${tests} texsyn_cli
                OUTPUT_QUIET RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building the GPL backends build failed: ${rc}")
endif()
foreach(t ${tests})
  execute_process(COMMAND ${WORK_DIR}/tests/${t} --gtest_brief=1 RESULT_VARIABLE rc)
  if(rc)
    message(FATAL_ERROR "${t} with the GPL backends failed: ${rc}")
  endif()
endforeach()
# Such a build says so.
execute_process(COMMAND ${WORK_DIR}/oiiotool-ext/texsyn --version RESULT_VARIABLE rc
                OUTPUT_VARIABLE out)
if(rc OR NOT out MATCHES "GPL build: FFTW, CGAL")
  message(FATAL_ERROR "texsyn --version of the GPL build does not say so: ${rc} ${out}")
endif()
