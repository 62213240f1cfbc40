# Helper functions shared by every folder. One function per target kind.

# Compiler warnings for project targets; -Werror when BLADEAXIS_STRICT is ON.
function(bladeaxis_set_warnings target)
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                             -Wno-sign-conversion)
    # GCC 12 reports false -Wrestrict positives on std::string concatenation at -O3
    # (GCC bug 105651); the warning is disabled rather than contorting every string build.
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
        target_compile_options(${target} PRIVATE -Wno-restrict)
    endif()
    if(BLADEAXIS_STRICT)
        target_compile_options(${target} PRIVATE -Werror)
    endif()
endfunction()

# bladeaxis_add_library(<module> SOURCES ... [DEPS ...] [PRIVATE_DEPS ...])
# Creates the static library bladeaxis_<module> with the ALIAS bladeaxis::<module>.
# Includes are written from the repository root ("core/base/error.h"). Every core library is
# installed for plug-ins (packaging/CMakeLists.txt exports the list BLADEAXIS_CORE_TARGETS).
function(bladeaxis_add_library module)
    cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
    set(target bladeaxis_${module})
    add_library(${target} STATIC ${ARG_SOURCES})
    add_library(bladeaxis::${module} ALIAS ${target})
    bladeaxis_core_interface(${target} PUBLIC)
    target_link_libraries(${target} PUBLIC ${ARG_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
    bladeaxis_set_warnings(${target})
endfunction()

# Include root of a core target: the source tree when built, include/bladeaxis when installed;
# exported as bladeaxis::<module>.
function(bladeaxis_core_interface target scope)
    target_include_directories(${target} ${scope}
        $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
        $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/bladeaxis>)
    string(REGEX REPLACE "^bladeaxis_" "" module ${target})
    set_target_properties(${target} PROPERTIES EXPORT_NAME ${module})
    set_property(GLOBAL APPEND PROPERTY BLADEAXIS_CORE_TARGETS ${target})
endfunction()

# bladeaxis_add_unit_test(<name> SOURCES ... DEPS ... [LABELS ...])
# One GoogleTest executable per module, registered with CTest test by test.
function(bladeaxis_add_unit_test name)
    cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;LABELS" ${ARGN})
    add_executable(${name} ${ARG_SOURCES})
    target_link_libraries(${name} PRIVATE ${ARG_DEPS} GTest::gtest GTest::gmock GTest::gtest_main)
    target_compile_definitions(${name} PRIVATE
        BLADEAXIS_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
        BLADEAXIS_TEST_DATA_DIR="${PROJECT_SOURCE_DIR}/tests/data")
    bladeaxis_set_warnings(${name})
    gtest_discover_tests(${name} PROPERTIES LABELS "unit;${ARG_LABELS}" DISCOVERY_TIMEOUT 60)
endfunction()

# bladeaxis_add_benchmark(<name> SOURCES ... DEPS ...)
function(bladeaxis_add_benchmark name)
    cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
    add_executable(${name} ${ARG_SOURCES})
    target_link_libraries(${name} PRIVATE ${ARG_DEPS} benchmark::benchmark)
    bladeaxis_set_warnings(${name})
    set_property(GLOBAL APPEND PROPERTY BLADEAXIS_BENCHMARKS ${name})
endfunction()

# bladeaxis_harden(<target>...)
# Debian's hardening flags on what the packages ship, in Release builds (dpkg-buildflags
# "hardening=+all" minus what the toolchain already does): _FORTIFY_SOURCE=2 (checked string
# and memory functions; needs the optimiser), -fstack-protector-strong, PIE, and full RELRO
# (-z relro -z now) on what is linked. A sanitizer or fuzzing build gets no _FORTIFY_SOURCE:
# AddressSanitizer intercepts the same functions, and the fortified variants hide errors from
# it. BLADEAXIS_HARDENING=OFF leaves every flag out.
function(bladeaxis_harden)
    if(NOT BLADEAXIS_HARDENING)
        return()
    endif()
    set(release $<CONFIG:Release,RelWithDebInfo,MinSizeRel>)
    set(sanitized FALSE)
    if(BLADEAXIS_FUZZ OR CMAKE_CXX_FLAGS MATCHES "-fsanitize")
        set(sanitized TRUE)
    endif()
    foreach(target IN LISTS ARGN)
        get_target_property(type ${target} TYPE)
        if(type STREQUAL "INTERFACE_LIBRARY") # headers only: nothing is compiled
            continue()
        endif()
        if(NOT sanitized)
            target_compile_options(${target} PRIVATE
                $<${release}:-U_FORTIFY_SOURCE> $<${release}:-D_FORTIFY_SOURCE=2>)
        endif()
        target_compile_options(${target} PRIVATE $<${release}:-fstack-protector-strong>)
        set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
        if(type MATCHES "EXECUTABLE|SHARED_LIBRARY|MODULE_LIBRARY")
            target_link_options(${target} PRIVATE $<${release}:LINKER:-z,relro,-z,now>)
        endif()
    endforeach()
endfunction()
