# Regenerates the CIE tables into IRID_OUTPUT and fails unless they equal IRID_COMMITTED.
include(${CMAKE_CURRENT_LIST_DIR}/../cmake/GenerateCieTables.cmake)
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${IRID_OUTPUT}" "${IRID_COMMITTED}"
                RESULT_VARIABLE different)
if(different)
    message(FATAL_ERROR "data/cie_tables.h is out of date with data/*.csv; run scripts/generate-cie-tables")
endif()
message(STATUS "data/cie_tables.h matches data/*.csv")
