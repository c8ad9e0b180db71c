# Installs the irid build into a scratch prefix, then configures, builds and runs the consumer
# project against it, and runs import_check.py on the installed Python package (IRID_PYTHON:
# the interpreter, empty without the module; IRID_PYTHON_DIR: its site-packages relative to the
# prefix; IRID_EXAMPLE_IMAGE: an image to read) with only that copy on the path.
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
if(IRID_PYTHON)
    set(site "${prefix}/${IRID_PYTHON_DIR}")
    if(NOT EXISTS "${site}/irid/__init__.py" OR NOT EXISTS "${site}/irid/__init__.pyi")
        message(FATAL_ERROR "cmake_consumer: the Python package is not installed in ${site}")
    endif()
    run(${CMAKE_COMMAND} -E env "PYTHONPATH=${site}" ${IRID_PYTHON}
        "${CMAKE_CURRENT_LIST_DIR}/import_check.py" "${site}" "${IRID_EXAMPLE_IMAGE}")
endif()
