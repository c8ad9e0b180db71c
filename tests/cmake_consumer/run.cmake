# Installs the irid build into a scratch prefix, then configures, builds and runs the consumer
# project against it.
cmake_minimum_required(VERSION 3.25)
set(prefix "${IRID_WORK_DIR}/install")
set(build "${IRID_WORK_DIR}/build")
file(REMOVE_RECURSE "${IRID_WORK_DIR}")

function(run)
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
    if(result)
        string(REPLACE ";" " " command "${ARGN}")
        message(FATAL_ERROR "cmake_consumer: '${command}' failed (${result})")
    endif()
endfunction()

run(${CMAKE_COMMAND} --install "${IRID_BUILD_DIR}" --prefix "${prefix}")
run(${CMAKE_COMMAND} -S "${IRID_CONSUMER_SOURCE}" -B "${build}" -G "${IRID_GENERATOR}"
    -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${prefix}")
run(${CMAKE_COMMAND} --build "${build}")
run("${build}/consumer")
