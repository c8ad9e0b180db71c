# irid_warnings: an INTERFACE target carrying the project's warning flags. Linked PRIVATE by
# every irid target, so consumers of the installed package do not inherit them.
add_library(irid_warnings INTERFACE)
target_compile_options(irid_warnings INTERFACE
    $<BUILD_INTERFACE:-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion
                      -Wnon-virtual-dtor -Wold-style-cast -Woverloaded-virtual>)
if(IRID_WARNINGS_AS_ERRORS)
    target_compile_options(irid_warnings INTERFACE $<BUILD_INTERFACE:-Werror>)
endif()
