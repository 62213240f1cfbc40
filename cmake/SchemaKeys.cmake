# bladeaxis_schema_keys(<target> SCHEMA <file> HEADER <name> NAMESPACE <ns> OBJECTS <name> <path> ...)
#
# The keys a file reader accepts, taken from the file's JSON Schema: for each object, named by
# its path of schema keywords ("properties,layer_edits,items"; "." for the root), an array
# `inline constexpr std::string_view k<name>[]` of its property names (sorted: CMake's JSON reader
# sorts an object's members),
# written to <binary dir>/generated/<name> and included as "generated/<name>". Made when CMake
# configures, and again whenever the schema changes, so a reader and its schema cannot drift.
function(bladeaxis_schema_keys target)
    cmake_parse_arguments(ARG "" "SCHEMA;HEADER;NAMESPACE" "OBJECTS" ${ARGN})
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${ARG_SCHEMA})
    file(READ ${ARG_SCHEMA} schema)
    file(RELATIVE_PATH source ${PROJECT_SOURCE_DIR} ${ARG_SCHEMA})
    set(text "#pragma once\n// Generated from ${source} by cmake/SchemaKeys.cmake: the keys each\n")
    string(APPEND text "// object of the file may hold. Do not edit; edit the schema.\n\n")
    string(APPEND text "#include <string_view>\n\nnamespace ${ARG_NAMESPACE} {\n")
    set(objects ${ARG_OBJECTS})
    while(objects)
        list(POP_FRONT objects name path)
        set(segments "")
        if(NOT path STREQUAL ".")
            string(REPLACE "," ";" segments "${path}")
        endif()
        string(JSON properties GET "${schema}" ${segments} properties)
        string(JSON count LENGTH "${properties}")
        math(EXPR last "${count} - 1")
        set(keys "")
        foreach(index RANGE ${last})
            string(JSON key MEMBER "${properties}" ${index})
            string(APPEND keys "    \"${key}\",\n")
        endforeach()
        string(APPEND text "\ninline constexpr std::string_view k${name}[] = {\n${keys}};\n")
    endwhile()
    string(APPEND text "\n} // namespace ${ARG_NAMESPACE}\n")
    set(header ${CMAKE_CURRENT_BINARY_DIR}/generated/${ARG_HEADER})
    file(CONFIGURE OUTPUT ${header} CONTENT "${text}" @ONLY)
    target_include_directories(${target} PRIVATE ${CMAKE_CURRENT_BINARY_DIR})
endfunction()
