# The asan preset (CMakePresets.json) builds in unity batches: CMAKE_UNITY_BUILD compiles each
# target's sources 8 to a translation unit. Under ASan at -O0 most of a file's compile time is the
# headers and the templates it instantiates (nlohmann::json, GoogleTest, the standard library),
# which a batch parses and generates once: 4 test files of tests/settings took 31 s of CPU one by
# one and 15 s as one unit. The release and debug presets compile file by file (ccache, quick
# incremental builds), so a clash below shows only in the asan build (./test.sh).
#
# A file whose file-local names (anonymous namespace, static) clash with a batch mate's is
# compiled alone here, rather than renamed: the names are right for their file. When the asan
# build fails with "redefinition of" or "declaration shadows" across two files, add the later one.
if(NOT CMAKE_UNITY_BUILD)
  return()
endif()

# st_compile_alone(TARGET FILE...): FILE (relative to the source tree) is its own unit in TARGET.
function(st_compile_alone target)
  foreach(file ${ARGN})
    set_property(SOURCE ${CMAKE_SOURCE_DIR}/${file} TARGET_DIRECTORY ${target}
      PROPERTY SKIP_UNITY_BUILD_INCLUSION ON)
  endforeach()
endfunction()

# One file per engine, each with its own addSplits / addBias / `using M = Mapping`.
set_target_properties(st_export PROPERTIES UNITY_BUILD OFF)
# tune_space.cpp's Json is nlohmann::json, its neighbours' nlohmann::ordered_json.
st_compile_alone(st_tune tune/tune_space.cpp)
# editor_accuracy.cpp: a local `using` shadows a neighbour's file-level alias (-Wshadow).
st_compile_alone(shadowtune app/editor/editor_accuracy.cpp)
if(TARGET editor_gl_test)
  st_compile_alone(editor_gl_test app/editor/editor_accuracy.cpp)
endif()
# Test files with their own kEye / kOverhead / sheetStack / readJson.
if(BUILD_TESTING)
  st_compile_alone(metrics_test tests/metrics/soft_truth_test.cpp tests/metrics/still_accuracy_test.cpp)
  st_compile_alone(render_gl_test tests/render/pass_work_gl_test.cpp)
  st_compile_alone(editor_smoke_test tests/editor/editor_xdotool_test.cpp tests/editor/editor_idle_test.cpp
    tests/editor/editor_preview_test.cpp)
endif()
# tune_panel.cpp: its own running / progress / runControls / chart beside sweep_panel.cpp's.
st_compile_alone(st_ui ui/tune_panel.cpp)
# editor_tune.cpp: its own kScanInterval / Clock / readJson beside editor_sweep.cpp's.
st_compile_alone(st_editor_model app/editor/editor_tune.cpp)
if(TARGET editor_tune_test)
  st_compile_alone(editor_tune_test app/editor/editor_tune.cpp)
endif()
