# FindFLINT: the FLINT number-theory library (Debian's libflint-dev 2.9 ships neither a CMake
# package nor a pkg-config file). Used by gkt's own build and installed beside gktConfig.cmake so
# that find_package(gkt) finds FLINT the same way.
#
# Result: FLINT_FOUND, FLINT_VERSION (from flint/flint.h), FLINT_INCLUDE_DIR (the directory that
# holds flint/, headers are included as <flint/fmpq.h>), FLINT_LIBRARY, and the imported target
# flint::flint.
find_path(FLINT_INCLUDE_DIR flint/fmpq.h)
find_library(FLINT_LIBRARY flint)
mark_as_advanced(FLINT_INCLUDE_DIR FLINT_LIBRARY)

if(FLINT_INCLUDE_DIR)
  foreach(_gkt_flint_header flint/flint.h flint/flint-config.h)
    if(NOT FLINT_VERSION AND EXISTS "${FLINT_INCLUDE_DIR}/${_gkt_flint_header}")
      file(STRINGS "${FLINT_INCLUDE_DIR}/${_gkt_flint_header}" _gkt_flint_version
           REGEX "^#define[ \t]+FLINT_VERSION[ \t]+\"[^\"]*\"")
      if(_gkt_flint_version)
        string(REGEX REPLACE ".*\"([^\"]*)\".*" "\\1" FLINT_VERSION "${_gkt_flint_version}")
      endif()
    endif()
  endforeach()
  unset(_gkt_flint_header)
  unset(_gkt_flint_version)
endif()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(FLINT REQUIRED_VARS FLINT_LIBRARY FLINT_INCLUDE_DIR VERSION_VAR FLINT_VERSION)

if(FLINT_FOUND AND NOT TARGET flint::flint)
  add_library(flint::flint UNKNOWN IMPORTED)
  set_target_properties(flint::flint PROPERTIES IMPORTED_LOCATION "${FLINT_LIBRARY}"
                                                INTERFACE_INCLUDE_DIRECTORIES "${FLINT_INCLUDE_DIR}")
endif()
