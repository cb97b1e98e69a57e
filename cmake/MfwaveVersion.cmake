# The git revision the build comes from, read once at configure time (`git describe --always --dirty`),
# so `--version` and every summary.json say which code produced a result. "unknown" when the source
# is not a git checkout of its own (a tarball, or an unpacked copy inside some other repository).
set(MFWAVE_GIT_REVISION "unknown")
find_package(Git QUIET)
if(GIT_FOUND)
  execute_process(COMMAND ${GIT_EXECUTABLE} rev-parse --show-toplevel
                  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
                  OUTPUT_VARIABLE _mfwave_git_top OUTPUT_STRIP_TRAILING_WHITESPACE
                  RESULT_VARIABLE _mfwave_git_status ERROR_QUIET)
  if(_mfwave_git_status EQUAL 0)
    file(REAL_PATH "${_mfwave_git_top}" _mfwave_git_top)
    file(REAL_PATH "${PROJECT_SOURCE_DIR}" _mfwave_source)
  endif()
  if(_mfwave_git_status EQUAL 0 AND _mfwave_git_top STREQUAL _mfwave_source)
    execute_process(COMMAND ${GIT_EXECUTABLE} describe --always --dirty
                    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
                    OUTPUT_VARIABLE _mfwave_describe OUTPUT_STRIP_TRAILING_WHITESPACE
                    RESULT_VARIABLE _mfwave_git_status ERROR_QUIET)
    if(_mfwave_git_status EQUAL 0 AND _mfwave_describe)
      set(MFWAVE_GIT_REVISION "${_mfwave_describe}")
    endif()
  endif()
endif()
message(STATUS "mfwave ${PROJECT_VERSION}, git revision ${MFWAVE_GIT_REVISION}")
