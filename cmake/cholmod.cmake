# CHOLMOD from Debian's libsuitesparse-dev has neither a CMake config nor a
# pkg-config file: find the header and the shared libraries and wrap them in an
# imported target. Link the shared library: it pulls in AMD, COLAMD, METIS, BLAS.
find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
find_library(CHOLMOD_LIBRARY NAMES libcholmod.so cholmod REQUIRED)
find_library(SUITESPARSECONFIG_LIBRARY NAMES libsuitesparseconfig.so suitesparseconfig REQUIRED)
add_library(SuiteSparse::CHOLMOD INTERFACE IMPORTED)
set_target_properties(SuiteSparse::CHOLMOD PROPERTIES
  INTERFACE_INCLUDE_DIRECTORIES "${CHOLMOD_INCLUDE_DIR}"
  INTERFACE_LINK_LIBRARIES "${CHOLMOD_LIBRARY};${SUITESPARSECONFIG_LIBRARY}")
message(STATUS "CHOLMOD: ${CHOLMOD_LIBRARY} (headers in ${CHOLMOD_INCLUDE_DIR})")
