# FindSuiteSparse: Debian's SuiteSparse 5.x ships neither a CMake config nor pkg-config files.
#
# Components: any of klu umfpack cholmod spqr amd colamd camd ccolamd btf suitesparseconfig.
# Defines SuiteSparse_FOUND and one imported target per component, SuiteSparse::<component>,
# with its headers (usually /usr/include/suitesparse) and the libraries it links against.

set(_ss_all_components suitesparseconfig amd camd colamd ccolamd btf cholmod klu umfpack spqr)
if(NOT SuiteSparse_FIND_COMPONENTS)
  set(SuiteSparse_FIND_COMPONENTS ${_ss_all_components})
endif()

# Dependencies between components (link order: a component before what it needs).
set(_ss_deps_suitesparseconfig "")
set(_ss_deps_amd suitesparseconfig)
set(_ss_deps_camd suitesparseconfig)
set(_ss_deps_colamd suitesparseconfig)
set(_ss_deps_ccolamd suitesparseconfig)
set(_ss_deps_btf "")
set(_ss_deps_cholmod amd camd colamd ccolamd suitesparseconfig)
set(_ss_deps_klu amd colamd btf suitesparseconfig)
set(_ss_deps_umfpack cholmod amd suitesparseconfig)
set(_ss_deps_spqr cholmod suitesparseconfig)

set(_ss_header_suitesparseconfig SuiteSparse_config.h)
set(_ss_header_amd amd.h)
set(_ss_header_camd camd.h)
set(_ss_header_colamd colamd.h)
set(_ss_header_ccolamd ccolamd.h)
set(_ss_header_btf btf.h)
set(_ss_header_cholmod cholmod.h)
set(_ss_header_klu klu.h)
set(_ss_header_umfpack umfpack.h)
set(_ss_header_spqr SuiteSparseQR.hpp)

# Expand the requested components with everything they depend on.
set(_ss_wanted ${SuiteSparse_FIND_COMPONENTS})
set(_ss_changed TRUE)
while(_ss_changed)
  set(_ss_changed FALSE)
  foreach(_c IN LISTS _ss_wanted)
    foreach(_d IN LISTS _ss_deps_${_c})
      if(NOT _d IN_LIST _ss_wanted)
        list(APPEND _ss_wanted ${_d})
        set(_ss_changed TRUE)
      endif()
    endforeach()
  endforeach()
endwhile()

find_path(SuiteSparse_INCLUDE_DIR SuiteSparse_config.h PATH_SUFFIXES suitesparse)
mark_as_advanced(SuiteSparse_INCLUDE_DIR)

set(_ss_required_vars SuiteSparse_INCLUDE_DIR)
foreach(_c IN LISTS _ss_wanted)
  find_library(SuiteSparse_${_c}_LIBRARY NAMES ${_c})
  find_file(SuiteSparse_${_c}_HEADER ${_ss_header_${_c}} PATHS ${SuiteSparse_INCLUDE_DIR} NO_DEFAULT_PATH)
  mark_as_advanced(SuiteSparse_${_c}_LIBRARY SuiteSparse_${_c}_HEADER)
  if(SuiteSparse_${_c}_LIBRARY AND SuiteSparse_${_c}_HEADER)
    set(SuiteSparse_${_c}_FOUND TRUE)
  else()
    set(SuiteSparse_${_c}_FOUND FALSE)
  endif()
endforeach()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(SuiteSparse
  REQUIRED_VARS ${_ss_required_vars}
  HANDLE_COMPONENTS)

if(SuiteSparse_FOUND)
  foreach(_c IN LISTS _ss_wanted)
    if(SuiteSparse_${_c}_FOUND AND NOT TARGET SuiteSparse::${_c})
      add_library(SuiteSparse::${_c} UNKNOWN IMPORTED)
      set_target_properties(SuiteSparse::${_c} PROPERTIES
        IMPORTED_LOCATION "${SuiteSparse_${_c}_LIBRARY}"
        INTERFACE_INCLUDE_DIRECTORIES "${SuiteSparse_INCLUDE_DIR}")
    endif()
  endforeach()
  foreach(_c IN LISTS _ss_wanted)
    if(TARGET SuiteSparse::${_c})
      set(_links "")
      foreach(_d IN LISTS _ss_deps_${_c})
        list(APPEND _links SuiteSparse::${_d})
      endforeach()
      if(_links)
        set_property(TARGET SuiteSparse::${_c} APPEND PROPERTY INTERFACE_LINK_LIBRARIES ${_links})
      endif()
    endif()
  endforeach()
endif()
