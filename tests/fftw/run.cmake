# SPDX-License-Identifier: Apache-2.0
# ctest driver: builds texsyn with the optional FFTW backend in a scratch tree and runs its
# FFT and pyramid tests, which compare FFTW with KissFFT. The default build (the one the
# rest of the suite tests) has no GPL code, so this is the only place FFTW is exercised.
# Inputs: SOURCE_DIR, WORK_DIR.
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}
                        -DCMAKE_BUILD_TYPE=Release -DTEXSYN_WITH_FFTW=ON -DTEXSYN_BUILD_BENCH=OFF
                OUTPUT_QUIET RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "configuring the FFTW build failed: ${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR} -j2 --target fft_test pyramid_test
                OUTPUT_QUIET RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building the FFTW build failed: ${rc}")
endif()
foreach(t fft_test pyramid_test)
  execute_process(COMMAND ${WORK_DIR}/tests/${t} --gtest_brief=1 RESULT_VARIABLE rc)
  if(rc)
    message(FATAL_ERROR "${t} with FFTW failed: ${rc}")
  endif()
endforeach()
