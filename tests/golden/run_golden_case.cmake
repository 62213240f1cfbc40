# Runs one golden case (see CMakeLists.txt in this folder for the layout).
file(REMOVE_RECURSE "${OUT_DIR}")
file(MAKE_DIRECTORY "${OUT_DIR}/out")
file(STRINGS "${CASE_DIR}/args.txt" raw_args)
set(args "")
foreach(arg IN LISTS raw_args)
    string(REPLACE "@DATA@" "${DATA_DIR}" arg "${arg}")
    string(REPLACE "@OUT@" "${OUT_DIR}/out" arg "${arg}")
    string(REPLACE "@SOURCE@" "${SOURCE_DIR}" arg "${arg}")
    list(APPEND args "${arg}")
endforeach()

execute_process(COMMAND "${PROGRAM}" ${args}
                RESULT_VARIABLE exit_code
                OUTPUT_FILE "${OUT_DIR}/stdout.txt"
                ERROR_FILE "${OUT_DIR}/stderr.txt"
                TIMEOUT 240)
file(READ "${CASE_DIR}/expect/exit_code" expected_exit)
string(STRIP "${expected_exit}" expected_exit)
set(failures "")
if(NOT exit_code STREQUAL expected_exit)
    file(READ "${OUT_DIR}/stderr.txt" stderr_text)
    list(APPEND failures "exit code ${exit_code}, expected ${expected_exit}; stderr: ${stderr_text}")
endif()

foreach(stream stdout stderr)
    if(EXISTS "${CASE_DIR}/expect/${stream}.txt")
        file(READ "${CASE_DIR}/expect/${stream}.txt" wanted)
        string(STRIP "${wanted}" wanted)
        string(REPLACE "@DATA@" "${DATA_DIR}" wanted "${wanted}")
        string(REPLACE "@OUT@" "${OUT_DIR}/out" wanted "${wanted}")
        file(READ "${OUT_DIR}/${stream}.txt" actual)
        string(FIND "${actual}" "${wanted}" found)
        if(found EQUAL -1)
            list(APPEND failures "${stream} does not contain '${wanted}'; it is:\n${actual}")
        endif()
    endif()
endforeach()

file(GLOB expected_files "${CASE_DIR}/expect/*.json" "${CASE_DIR}/expect/*.csv")
foreach(expected IN LISTS expected_files)
    get_filename_component(name "${expected}" NAME)
    execute_process(COMMAND "${COMPARE}" "${expected}" "${OUT_DIR}/out/${name}"
                    RESULT_VARIABLE same OUTPUT_VARIABLE diff ERROR_VARIABLE diff)
    if(NOT same EQUAL 0)
        list(APPEND failures "${name} differs from the reference (actual: ${OUT_DIR}/out/${name}):\n${diff}")
    endif()
endforeach()

if(failures)
    list(JOIN failures "\n" text)
    message(FATAL_ERROR "golden case ${CASE_DIR} failed:\n${text}\n(rebaseline after review: tests/golden/rebaseline.sh)")
endif()
