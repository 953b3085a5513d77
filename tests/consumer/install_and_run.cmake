# Test install_consumer: installs a wheelwear build into a fresh prefix, then configures, builds
# and runs the consumer project of this folder against that prefix alone. Builds nothing of
# the project itself: the build must be complete (ctest runs after it).
#
#   cmake -DBUILD_DIR=<wheelwear build> -DWORK_DIR=<scratch dir> -DCXX_COMPILER=<c++>
#         [-DC_COMPILER=<cc>] [-DCONFIG=Release] [-DGENERATOR=...] [-DMAKE_PROGRAM=...] [-DLAUNCHER=ccache]
#         -P install_and_run.cmake
cmake_minimum_required(VERSION 3.25)

foreach(var BUILD_DIR WORK_DIR CXX_COMPILER)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "install_and_run.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT CONFIG)
  set(CONFIG Release)
endif()
set(source_dir ${CMAKE_CURRENT_LIST_DIR})
set(prefix ${WORK_DIR}/prefix)
set(consumer_build ${WORK_DIR}/build)
file(REMOVE_RECURSE ${WORK_DIR})

# run(STEP COMMAND...): runs COMMAND, showing its output only when it fails.
function(run step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE output
                  ERROR_VARIABLE output)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${step} failed (${status}):\n${output}")
  endif()
  message(STATUS "${step}: ok")
endfunction()

run("install into ${prefix}" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix}
    --config ${CONFIG})

# The consumer gets the compiler, and no flags from the environment, so that what its compile
# and link lines hold comes from the package alone.
foreach(var CFLAGS CXXFLAGS LDFLAGS CMAKE_PREFIX_PATH)
  unset(ENV{${var}})
endforeach()
set(configure ${CMAKE_COMMAND} -S ${source_dir} -B ${consumer_build}
    -DCMAKE_BUILD_TYPE=${CONFIG} -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
    -DCMAKE_EXPORT_COMPILE_COMMANDS=ON)
# The package enables C for FindHDF5: the project's C compiler, too.
if(C_COMPILER)
  list(APPEND configure -DCMAKE_C_COMPILER=${C_COMPILER})
endif()
if(GENERATOR)
  list(APPEND configure -G ${GENERATOR})
endif()
if(MAKE_PROGRAM)
  list(APPEND configure -DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM})
endif()
if(LAUNCHER)
  list(APPEND configure -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
run("configure the consumer" ${configure})

# The package found must be the one just installed, not a build tree or a system copy.
file(STRINGS ${consumer_build}/CMakeCache.txt found REGEX "^wheelwear_DIR:")
string(REGEX REPLACE "^[^=]*=" "" found "${found}")
file(REAL_PATH ${prefix} real_prefix)
file(REAL_PATH "${found}" real_found)
string(FIND "${real_found}/" "${real_prefix}/" at)
if(NOT at EQUAL 0)
  message(FATAL_ERROR "found wheelwear in ${found}, not in ${prefix}")
endif()

# The project's warnings, architecture and instrumentation must not reach the consumer.
set(lines "")
foreach(file compile_commands.json CMakeFiles/wheelwear_consumer.dir/link.txt build.ninja)
  if(EXISTS ${consumer_build}/${file})
    file(READ ${consumer_build}/${file} text)
    string(APPEND lines "${text}")
  endif()
endforeach()
foreach(flag -Wall -Wextra -Wconversion -Wshadow -march=native -fsanitize -fno-math-errno)
  string(FIND "${lines}" "${flag}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "the consumer's compile or link line holds ${flag}:\n${lines}")
  endif()
endforeach()
message(STATUS "consumer flags: none of the project's")

run("build the consumer" ${CMAKE_COMMAND} --build ${consumer_build} --config ${CONFIG})

set(exe ${consumer_build}/wheelwear_consumer)
if(NOT EXISTS ${exe})
  set(exe ${consumer_build}/${CONFIG}/wheelwear_consumer)
endif()
# The installed data, not the source tree's.
set(ENV{WHEELWEAR_DATA_DIR} ${prefix}/share/wheelwear)
execute_process(COMMAND ${exe} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the consumer failed (${status})")
endif()
