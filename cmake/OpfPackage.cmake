# Installing and exporting: find_package(opf) (opfConfig.cmake, a version file, namespaced
# targets opf::filter, opf::estimators, opf::io, opf::opf and the components opf::mrpt_bridge,
# opf::vision, opf::sim), pkg-config
# (opf.pc: the libraries of opf::opf), the umbrella header <opf/opf.h>, and a .deb through CPack.
include(CMakePackageConfigHelpers)

# The umbrella header, staged and installed at <opf/opf.h>.
set(OPF_UMBRELLA_ROOT ${PROJECT_BINARY_DIR}/include/umbrella)
file(MAKE_DIRECTORY ${OPF_UMBRELLA_ROOT}/opf)
file(CREATE_LINK ${PROJECT_SOURCE_DIR}/lib/opf.h ${OPF_UMBRELLA_ROOT}/opf/opf.h SYMBOLIC)
target_include_directories(opf_opf INTERFACE $<BUILD_INTERFACE:${OPF_UMBRELLA_ROOT}>)
install(FILES ${PROJECT_SOURCE_DIR}/lib/opf.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/opf)

set(OPF_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/opf)
foreach(set opfTargets opfMrptBridgeTargets opfVisionTargets opfSimTargets)
  install(EXPORT ${set} NAMESPACE opf:: DESTINATION ${OPF_CMAKE_DIR})
endforeach()
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/opfConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/opfConfig.cmake
                              INSTALL_DESTINATION ${OPF_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/opfConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/opfConfig.cmake ${PROJECT_BINARY_DIR}/opfConfigVersion.cmake
        DESTINATION ${OPF_CMAKE_DIR})

# pkg-config: the opf::opf libraries, lowest layer last, and what they link. MRPT ships no .pc
# files on Debian 12, so its include folders and libraries are spelled out from its targets.
set(OPF_PC_MRPT_INCLUDES "")
foreach(module poses bayes obs random math core system serialization io containers rtti
               typemeta config img)
  if(EXISTS /usr/include/mrpt/${module}/include)
    string(APPEND OPF_PC_MRPT_INCLUDES " -I/usr/include/mrpt/${module}/include")
  endif()
endforeach()
# Relocatable: the prefix is found from the .pc file's own place, as `cmake --install --prefix`
# may put it anywhere.
file(RELATIVE_PATH OPF_PC_UP /root/${CMAKE_INSTALL_LIBDIR}/pkgconfig /root)
string(REGEX REPLACE "/$" "" OPF_PC_UP "${OPF_PC_UP}")
configure_file(${PROJECT_SOURCE_DIR}/cmake/opf.pc.in ${PROJECT_BINARY_DIR}/opf.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/opf.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

set(CPACK_PACKAGE_NAME opf-toolkit)
set(CPACK_PACKAGE_VENDOR "Object Permanence Filter toolkit")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "Object Permanence Filter: 6-DoF tracking through occlusion (library, headers, opf program)")
set(CPACK_PACKAGE_CONTACT "opf-toolkit maintainers <opf@localhost>")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "libmrpt-poses-dev, libmrpt-obs-dev, libmrpt-opengl-dev, libceres-dev, libeigen3-dev, libyaml-cpp-dev, libopencv-dev")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
include(CPack)
