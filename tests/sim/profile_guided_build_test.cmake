# sim.profile_guided_build_same_results: runs the same simulations with the simulator compiled
# without the profile (the instrumented copy, highlift_sim_training) and with it
# (highlift_sim_profiled_results, on highlift_sim), and requires the same statistics, events, peak
# torques and peak times, printed as hexadecimal floating point.
#
#   cmake -DWITHOUT_PROFILE=<exe> -DWITH_PROFILE=<exe> -DPROJECT_FILE=<json> -DRUNS=<run;...>
#         -DSCRATCH=<dir> -P profile_guided_build_test.cmake
foreach(var WITHOUT_PROFILE WITH_PROFILE PROJECT_FILE RUNS SCRATCH)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "profile_guided_build_test.cmake needs -D${var}=...")
  endif()
endforeach()

# The instrumented program writes its counts under GCOV_PREFIX, here a scratch folder, so that
# the test leaves the build's own profile as the training made it.
file(REMOVE_RECURSE ${SCRATCH})
file(MAKE_DIRECTORY ${SCRATCH})
execute_process(
  COMMAND ${CMAKE_COMMAND} -E env GCOV_PREFIX=${SCRATCH} ${WITHOUT_PROFILE} --results ${PROJECT_FILE} ${RUNS}
  RESULT_VARIABLE without_status OUTPUT_VARIABLE without ERROR_VARIABLE without_error)
execute_process(
  COMMAND ${WITH_PROFILE} --results ${PROJECT_FILE} ${RUNS}
  RESULT_VARIABLE with_status OUTPUT_VARIABLE with ERROR_VARIABLE with_error)
file(REMOVE_RECURSE ${SCRATCH})

if(NOT without_status EQUAL 0 OR NOT with_status EQUAL 0)
  message(FATAL_ERROR "a run failed (without the profile: exit ${without_status}, with it: exit ${with_status})\n"
                      "${without}${without_error}\n${with}${with_error}")
endif()
string(REGEX MATCHALL "  peak [^\n]*" peaks "${with}")
list(LENGTH peaks n_peaks)
if(n_peaks LESS 100)
  message(FATAL_ERROR "expected the peak torques of every element, found ${n_peaks} lines:\n${with}")
endif()
if(NOT without STREQUAL with)
  string(REPLACE "\n" ";" a "${without}")
  string(REPLACE "\n" ";" b "${with}")
  list(LENGTH a na)
  list(LENGTH b nb)
  set(n ${na})
  if(nb LESS n)
    set(n ${nb})
  endif()
  math(EXPR last "${n} - 1")
  foreach(i RANGE ${last})
    list(GET a ${i} la)
    list(GET b ${i} lb)
    if(NOT la STREQUAL lb)
      math(EXPR line "${i} + 1")
      message(FATAL_ERROR "the profile-guided simulator gives other results; first difference at line ${line}:\n"
                          "  without the profile: ${la}\n  with the profile:    ${lb}")
    endif()
  endforeach()
  message(FATAL_ERROR "the outputs differ in length (${na} lines without the profile, ${nb} with it):\n"
                      "${without}\n---\n${with}")
endif()
message(STATUS "the same results with and without the profile: ${n_peaks} peak torques and their times, "
               "the events and the solver statistics of ${RUNS}")
