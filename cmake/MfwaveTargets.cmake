# Helpers that give every project target the same standard, warnings and layout.

include(GNUInstallDirs)

# Warnings for project code only: dependencies come in through imported targets, whose
# headers are SYSTEM includes and so stay quiet.
function(mfwave_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                           -Wold-style-cast -Wcast-align -Woverloaded-virtual)
  if(MFWAVE_WARNINGS_AS_ERRORS)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# mfwave_add_library(<folder> SOURCES ... DEPENDS ...)
# One static library per concept folder under lib/, target mfwave_<folder>, alias mfwave::<folder>.
# Headers are included as "<folder>/<Name>.hpp" relative to lib/.
function(mfwave_add_library folder)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
  set(target mfwave_${folder})
  # The layering, enforced: a library's include directory shows its own folder only, as one link
  # <build>/include/<target>/<folder under lib/> -> lib/<folder>. Includes keep their usual form
  # ("io/run/RunSummary.hpp"), and a file finds the headers of its own folder and of the libraries
  # it links (their directories are PUBLIC, so they pass along the DEPENDS chain) and no others:
  # including what a target does not link fails to compile. Libraries that share a folder (the
  # numerics and numerics_fft; the spectra_* ones) share its headers.
  file(RELATIVE_PATH relative ${PROJECT_SOURCE_DIR}/lib ${CMAKE_CURRENT_SOURCE_DIR})
  set(includes ${PROJECT_BINARY_DIR}/include/${target})
  get_filename_component(parent ${includes}/${relative} DIRECTORY)
  file(MAKE_DIRECTORY ${parent})
  file(CREATE_LINK ${CMAKE_CURRENT_SOURCE_DIR} ${includes}/${relative} SYMBOLIC)
  # Installed, the headers of every library sit side by side under include/mfwave/<folder under lib/>
  # (the real files, not the links), so a user's "io/run/RunSummary.hpp" and the headers' own
  # includes resolve against one directory; the installed layering is not enforced.
  if(ARG_SOURCES)
    add_library(${target} STATIC ${ARG_SOURCES})
    target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${includes}>
                                                $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/mfwave>)
    target_link_libraries(${target} PUBLIC ${ARG_DEPENDS})
    mfwave_set_warnings(${target})
    if(MFWAVE_UNITY_LIBRARIES)
      set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 8)
    endif()
  else()
    add_library(${target} INTERFACE)
    target_include_directories(${target} INTERFACE $<BUILD_INTERFACE:${includes}>
                                                   $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/mfwave>)
    target_link_libraries(${target} INTERFACE ${ARG_DEPENDS})
  endif()
  add_library(mfwave::${folder} ALIAS ${target})
  # Exported as mfwave::<folder>, the name the build tree uses (cmake/MfwaveInstall.cmake).
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${folder})
  install(TARGETS ${target} EXPORT mfwaveTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/mfwave/${relative}
          FILES_MATCHING PATTERN "*.hpp")
endfunction()

# mfwave_add_test(<name> SOURCES ... DEPENDS ...): a GoogleTest executable registered with CTest.
function(mfwave_add_test name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS;LABELS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPENDS} GTest::gtest_main)
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR}/tests)  # tests/support/
  mfwave_set_warnings(${name})
  if(MFWAVE_UNITY_TESTS)
    set_target_properties(${name} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 8)
  endif()
  set(labels unit)
  if(ARG_LABELS)
    set(labels ${ARG_LABELS})
  endif()
  gtest_discover_tests(${name} PROPERTIES LABELS "${labels}" DISCOVERY_TIMEOUT 60)
endfunction()

# mfwave_add_executable(<name> SOURCES ... DEPENDS ...): a driver or analysis tool.
function(mfwave_add_executable name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPENDS})
  mfwave_set_warnings(${name})
  install(TARGETS ${name} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endfunction()
