# Debian's libosmium2-dev installs headers only and no CMake package, so this
# module finds the headers and the libraries its I/O component needs.
# Result: target Osmium::Osmium (header-only plus PBF/XML/gzip/bzip2 support).
find_path(OSMIUM_INCLUDE_DIR osmium/version.hpp)
find_path(PROTOZERO_INCLUDE_DIR protozero/version.hpp)

set(_osmium_deps_found TRUE)
if("io" IN_LIST Osmium_FIND_COMPONENTS)
  find_package(ZLIB QUIET)
  find_package(BZip2 QUIET)
  find_package(EXPAT QUIET)
  find_package(Threads QUIET)
  foreach(_dep ZLIB_FOUND BZIP2_FOUND EXPAT_FOUND Threads_FOUND)
    if(NOT ${_dep})
      set(_osmium_deps_found FALSE)
    endif()
  endforeach()
  set(Osmium_io_FOUND ${_osmium_deps_found})
endif()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Osmium
  REQUIRED_VARS OSMIUM_INCLUDE_DIR PROTOZERO_INCLUDE_DIR
  HANDLE_COMPONENTS)

if(Osmium_FOUND AND NOT TARGET Osmium::Osmium)
  add_library(Osmium::Osmium INTERFACE IMPORTED)
  target_include_directories(Osmium::Osmium INTERFACE
    ${OSMIUM_INCLUDE_DIR} ${PROTOZERO_INCLUDE_DIR})
  if(Osmium_io_FOUND)
    target_link_libraries(Osmium::Osmium INTERFACE
      ZLIB::ZLIB BZip2::BZip2 EXPAT::EXPAT Threads::Threads)
  endif()
endif()
mark_as_advanced(OSMIUM_INCLUDE_DIR PROTOZERO_INCLUDE_DIR)
