# MeshLab 2025.07 plugin variants (included by filter_quasidev/meshlab/CMakeLists.txt).
# Both compile filter_plugin_2025.{h,cpp} + the shared adapter against the Debian 2025.07 source
# headers fetched by scripts/setup.sh (third_party/meshlab-2025.07):
#  - pymeshlab: double / "2025.07d", linked against the pymeshlab wheel's own
#    pymeshlab/lib/libmeshlab-common.so (scripts/setup_pymeshlab.sh installs the wheel into .venv)
#    -> bin/pymeshlab/libfilter_quasidev.so. `pymeshlab.load_plugin()` accepts it (tests/pymeshlab).
#  - meshlab2025: float / "2025.07" for the MeshLab 2025.07 application. No float 2025.07
#    libmeshlab-common exists here, so it links a soname-only stub (docs/meshlab-notes.md
#    "The 2025.07 plugins"), which gives the DT_NEEDED entry the application resolves at load
#    time -> bin/meshlab2025/.
# What the wheel needs from a plugin (verified, see tests/pymeshlab/test_wheel_abi.py):
#  DT_NEEDED libmeshlab-common.so (the host dlopens extensions RTLD_LOCAL), no other library the
#  wheel lacks (so no libGLEW: the wheel ships libexternal-glew.so instead, and no libcholmod:
#  both link qd_core_eigen, the engine without CHOLMOD), no RUNPATH into the
#  venv, Qt 5.15 (the wheel bundles qt.io Qt 5.15.2; plugins built with Debian's 5.15.8 load).

set(QD_MESHLAB2025_SOURCE_DIR "${PROJECT_SOURCE_DIR}/third_party/meshlab-2025.07"
    CACHE PATH "MeshLab 2025.07 source root (holds src/common and src/vcglib)")
set(QD_PYMESHLAB_LIB_DIR "" CACHE PATH
    "pymeshlab/lib of the installed pymeshlab 2025.7.post1 wheel (empty: looked up in <repo>/.venv)")
set(_qd_wheel_lib "${QD_PYMESHLAB_LIB_DIR}")
if(NOT _qd_wheel_lib)  # looked up at every configure, so a venv made later is found
  file(GLOB _qd_wheel_libs "${PROJECT_SOURCE_DIR}/.venv/lib/python3*/site-packages/pymeshlab/lib")
  if(_qd_wheel_libs)
    list(GET _qd_wheel_libs 0 _qd_wheel_lib)
  endif()
endif()

set(_qd_2025_sources ${CMAKE_CURRENT_SOURCE_DIR}/filter_plugin_2025.cpp
                     ${CMAKE_CURRENT_SOURCE_DIR}/filter_plugin_2025.h)
set(_qd_2025_includes "${QD_MESHLAB2025_SOURCE_DIR}/src" "${QD_MESHLAB2025_SOURCE_DIR}/src/vcglib")

# Links only what is needed (keeps the Qt/GLEW libraries the headers want but the code does not
# call out of DT_NEEDED) and takes GLEW's headers without its library: libmeshlab-common's own
# GLEW symbols would otherwise make the linker record libGLEW.so.2.2, which the wheel lacks.
function(qd_meshlab2025_link_only_needed target)
  get_target_property(libs ${target} LINK_LIBRARIES)
  list(REMOVE_ITEM libs GLEW::GLEW)
  set_target_properties(${target} PROPERTIES LINK_LIBRARIES "${libs}" SKIP_BUILD_RPATH ON)
  target_include_directories(${target} SYSTEM PRIVATE
                             $<TARGET_PROPERTY:GLEW::GLEW,INTERFACE_INCLUDE_DIRECTORIES>)
  target_link_options(${target} PRIVATE -Wl,--as-needed)
endfunction()

if(NOT EXISTS "${QD_MESHLAB2025_SOURCE_DIR}/src/common/plugins/interfaces/filter_plugin.h"
   OR NOT Qt5_FOUND OR NOT GLEW_FOUND)
  message(STATUS "MeshLab 2025.07 plugins NOT built: need ${QD_MESHLAB2025_SOURCE_DIR}/src/common "
                 "(run scripts/setup.sh), Qt5 (qtbase5-dev, libqt5opengl5-dev) and GLEW (libglew-dev)")
  return()
endif()

# pymeshlab 2025.7.post1 (double, "2025.07d"), linked against the wheel's libmeshlab-common.so.
if(EXISTS "${_qd_wheel_lib}/libmeshlab-common.so")
  qd_add_meshlab_plugin(filter_quasidev_pymeshlab CORE qd_core_eigen
    SOURCES ${_qd_2025_sources}
    SYSTEM_INCLUDES ${_qd_2025_includes}
    DEFINITIONS MESHLAB_SCALAR=double MESHLAB_VERSION=2025.07d
    LIBRARIES "${_qd_wheel_lib}/libmeshlab-common.so"
    OUTPUT_DIR "${CMAKE_BINARY_DIR}/bin/pymeshlab" OUTPUT_NAME filter_quasidev)
  qd_meshlab2025_link_only_needed(filter_quasidev_pymeshlab)
  message(STATUS "pymeshlab 2025.07d plugin: ${CMAKE_BINARY_DIR}/bin/pymeshlab/libfilter_quasidev.so")
else()
  message(STATUS "pymeshlab 2025.07d plugin NOT built: no pymeshlab wheel found (QD_PYMESHLAB_LIB_DIR="
                 "'${QD_PYMESHLAB_LIB_DIR}', <repo>/.venv): run scripts/setup_pymeshlab.sh")
endif()

# MeshLab 2025.07 application (float, "2025.07"), against a soname-only libmeshlab-common stub.
set(_qd_stub_source "${CMAKE_CURRENT_BINARY_DIR}/meshlab_common_stub.cpp")
file(WRITE "${_qd_stub_source}.in"
     "// soname-only stand-in for MeshLab 2025.07's libmeshlab-common.so (link time only)\n")
configure_file("${_qd_stub_source}.in" "${_qd_stub_source}" COPYONLY)
add_library(qd_meshlab2025_common_stub SHARED "${_qd_stub_source}")
set_target_properties(qd_meshlab2025_common_stub PROPERTIES
  OUTPUT_NAME meshlab-common
  LIBRARY_OUTPUT_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}/meshlab2025_stub")
qd_add_meshlab_plugin(filter_quasidev_meshlab2025 ALLOW_UNDEFINED CORE qd_core_eigen
  SOURCES ${_qd_2025_sources}
  SYSTEM_INCLUDES ${_qd_2025_includes}
  DEFINITIONS MESHLAB_SCALAR=float MESHLAB_VERSION=2025.07
  LIBRARIES "-Wl,--push-state,--no-as-needed" qd_meshlab2025_common_stub "-Wl,--pop-state"
  OUTPUT_DIR "${CMAKE_BINARY_DIR}/bin/meshlab2025" OUTPUT_NAME filter_quasidev)
qd_meshlab2025_link_only_needed(filter_quasidev_meshlab2025)
message(STATUS "MeshLab 2025.07 (float) plugin, compile-checked, stub-linked: "
               "${CMAKE_BINARY_DIR}/bin/meshlab2025/libfilter_quasidev.so")
