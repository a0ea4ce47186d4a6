# One static library per source folder, each seeing only the headers of the folders it links.
#
# A folder's headers are included as <opf/FOLDER/header.h>. The build stages each folder under
# its own include root (build/include/FOLDER/opf/FOLDER, a symbolic link to the sources), and a
# library's include path holds only its own root and, through linking, the roots of the folders
# below it: an include that runs the wrong way finds no header and fails to build.
#
#   opf_folder_library(<folder> [DIRECTORY <dir>] [PUBLIC <targets>...] [PRIVATE <targets>...]
#                      [PRIVATE_HEADERS <header>...] [EXPORT <set>])
#
# defines target opf_<folder> (exported as opf::<folder>) from <dir>/*.cpp (default:
# lib/<folder>), installs its headers under include/opf/<folder>/ except PRIVATE_HEADERS, and
# adds it to the export set <set> (default opfTargets).
function(opf_folder_library folder)
  cmake_parse_arguments(ARG "" "DIRECTORY;EXPORT" "PUBLIC;PRIVATE;PRIVATE_HEADERS" ${ARGN})
  if(NOT ARG_EXPORT)
    set(ARG_EXPORT opfTargets)
  endif()
  if(NOT ARG_DIRECTORY)
    set(ARG_DIRECTORY ${PROJECT_SOURCE_DIR}/lib/${folder})
  endif()
  set(root ${PROJECT_BINARY_DIR}/include/${folder})
  file(MAKE_DIRECTORY ${root}/opf)
  file(CREATE_LINK ${ARG_DIRECTORY} ${root}/opf/${folder} SYMBOLIC)

  file(GLOB sources CONFIGURE_DEPENDS ${ARG_DIRECTORY}/*.cpp)
  set(target opf_${folder})
  add_library(${target} STATIC ${sources})
  add_library(opf::${folder} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${folder})
  target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${root}>
                                              $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(${target} PUBLIC ${ARG_PUBLIC} PRIVATE ${ARG_PRIVATE}
                                                               $<BUILD_INTERFACE:opf_warnings>)

  install(TARGETS ${target} EXPORT ${ARG_EXPORT} ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  file(GLOB headers ${ARG_DIRECTORY}/*.h)
  foreach(private IN LISTS ARG_PRIVATE_HEADERS)
    list(REMOVE_ITEM headers ${ARG_DIRECTORY}/${private})
  endforeach()
  install(FILES ${headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/opf/${folder})
endfunction()
