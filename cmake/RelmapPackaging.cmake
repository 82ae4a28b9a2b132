# Installation and the Debian package: `cpack -G DEB` in the build directory makes
# relmap_<version>_<arch>.deb with the four programs, the systemd unit, its settings
# and the deploy/ examples; dpkg-shlibdeps computes the runtime dependencies from
# the binaries, so `apt install ./relmap_*.deb` pulls exactly the libraries they need.
#
# One package, not one per program: the programs share their libraries (gRPC,
# protobuf, PCL for the server and the CLI), a lab machine wants both ends, and one
# version of client and server can never be installed against the other's skew.
include(GNUInstallDirs)

foreach(program relmap-server relmap relmap-sim relmap-robot)
  if(TARGET ${program})
    install(TARGETS ${program} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  endif()
endforeach()

# relmap-sim's scenes. Its default folder is the source tree's, so an installed
# relmap-sim needs RELMAP_SIM_SCENES_DIR=/usr/share/relmap/scenes (the image sets it).
if(TARGET relmap-sim)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/sim_backend/scenes/
          DESTINATION ${CMAKE_INSTALL_DATADIR}/relmap/scenes FILES_MATCHING PATTERN "*.json")
endif()

set(RELMAP_DEPLOY_DIR ${PROJECT_SOURCE_DIR}/deploy)
# Under the prefix: /usr/lib/systemd/system in the package (Debian, merged /usr),
# /usr/local/lib/systemd/system for a plain `cmake --install` (systemd reads both).
install(FILES ${RELMAP_DEPLOY_DIR}/systemd/relmap-server.service
        DESTINATION lib/systemd/system)
# The settings are a conffile: an upgrade keeps the administrator's edits.
install(FILES ${RELMAP_DEPLOY_DIR}/systemd/relmap-server.conf DESTINATION /etc/relmap)
install(FILES ${RELMAP_DEPLOY_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR}/deploy)
install(FILES ${RELMAP_DEPLOY_DIR}/nginx/relmap.conf.in
        DESTINATION ${CMAKE_INSTALL_DOCDIR}/deploy/nginx)
install(PROGRAMS ${RELMAP_DEPLOY_DIR}/nginx/render-conf
        DESTINATION ${CMAKE_INSTALL_DOCDIR}/deploy/nginx)
install(FILES ${RELMAP_DEPLOY_DIR}/envoy/envoy.yaml DESTINATION ${CMAKE_INSTALL_DOCDIR}/deploy/envoy)

set(CPACK_PACKAGE_NAME relmap)
set(CPACK_PACKAGE_VENDOR "relmap")
set(CPACK_PACKAGE_CONTACT "relmap maintainers <relmap@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "relevance maps by interactive perception: gRPC server, CLI, simulator, robot adapter")
string(CONCAT CPACK_PACKAGE_DESCRIPTION
       "relmap-server learns, per session, which supervoxels of a scene a robot can move\n"
       "(Le Goff et al. 2018); relmap is its command-line client, relmap-sim an\n"
       "ODE-simulated pusher and relmap-robot the adapter for a real camera and arm.")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS OFF)
# systemd is what runs the unit; the programs themselves run without it.
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "systemd, nginx")
set(RELMAP_DEB_CONFFILES ${CMAKE_CURRENT_BINARY_DIR}/deb/conffiles)
file(WRITE ${RELMAP_DEB_CONFFILES} "/etc/relmap/relmap-server.conf\n")
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA ${RELMAP_DEB_CONFFILES})
include(CPack)
