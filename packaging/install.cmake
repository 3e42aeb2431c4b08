# `cmake --install` and the Debian package (CPack, DEB generator): the program,
# its bash completion, a desktop entry opening the default scene, and the data
# it reads at run time under <prefix>/share/coilsim (app/data_paths.h finds them
# there from <prefix>/bin/coilsim). Shaders are embedded in the binary.
include(GNUInstallDirs)

set(COILSIM_INSTALL_DATA_REL ${CMAKE_INSTALL_DATADIR}/coilsim)
install(TARGETS coilsim RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# Scenes name their meshes relative to themselves (../assets/meshes): the tree is kept.
install(DIRECTORY assets/coils assets/meshes DESTINATION ${COILSIM_INSTALL_DATA_REL}/assets
        PATTERN "make-catalogue.sh" EXCLUDE)
install(DIRECTORY scenes timelines examples DESTINATION ${COILSIM_INSTALL_DATA_REL})
install(FILES README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR})

# The completion script is what the program itself prints (from its command table).
set(COILSIM_COMPLETION ${PROJECT_BINARY_DIR}/packaging/coilsim.bash)
add_custom_command(OUTPUT ${COILSIM_COMPLETION}
                   COMMAND ${CMAKE_COMMAND} -E make_directory ${PROJECT_BINARY_DIR}/packaging
                   COMMAND coilsim completion bash > ${COILSIM_COMPLETION}
                   DEPENDS coilsim
                   COMMENT "bash completion from coilsim's command table")
add_custom_target(coilsim_completion ALL DEPENDS ${COILSIM_COMPLETION})
install(FILES ${COILSIM_COMPLETION} DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME coilsim)

# The desktop entry names the installed program and scene by absolute path.
install(CODE "
  set(COILSIM_INSTALL_BINARY \"\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_BINDIR}/coilsim\")
  set(COILSIM_INSTALL_DATA \"\${CMAKE_INSTALL_PREFIX}/${COILSIM_INSTALL_DATA_REL}\")
  configure_file(\"${PROJECT_SOURCE_DIR}/packaging/coilsim.desktop.in\" \"${PROJECT_BINARY_DIR}/packaging/coilsim.desktop\" @ONLY)
  file(INSTALL \"${PROJECT_BINARY_DIR}/packaging/coilsim.desktop\"
       DESTINATION \"\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_DATADIR}/applications\")
")

set(CPACK_PACKAGE_NAME coilsim)
set(CPACK_PACKAGE_VENDOR "coilsim")
set(CPACK_PACKAGE_CONTACT "coilsim maintainers <coilsim@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Simulator of coil embolization of brain aneurysms")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
# The shared libraries' packages (GLFW, OSMesa, assimp, FCL, NLopt ...) from dpkg-shlibdeps.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
include(CPack)
