# Fails when a file under SRC includes from a layer above its own (or beside
# it): the layers point one way (docs/architecture.md).
#   cmake -DSRC=<folder of layer folders> -P check_layers.cmake
# Rank per folder: a file may include its own folder and lower ranks only.
set(rank_base 0)      # input files, quoting, number formatting, InputError: the standard library only
set(rank_core 1)      # physics only: Eigen, Boost.Math and base
set(rank_io 2)
set(rank_viz 2)
set(rank_scene 3)     # the TOML reader fills viz's option structs (viz/draw_options.hpp)
set(rank_compose 4)   # frame composition: scene + viz -> draw lists, view rectangles, layout report (GL-free)
set(rank_render 5)
set(rank_golden 5)
set(rank_gltf 5)   # glTF export (tinygltf): core, io, scene and viz, beside render
set(rank_run 6)
set(rank_app 7)
set(rank_bench 8)  # studies, peers, render and micro benchmarks, tumble-bench, tumble_docs: above the app, included by none

if(NOT IS_DIRECTORY "${SRC}")
  message(FATAL_ERROR "SRC='${SRC}' is not a folder")
endif()
file(GLOB layers RELATIVE "${SRC}" "${SRC}/*")
set(errors "")
set(files_checked 0)
foreach(layer IN LISTS layers)
  if(NOT IS_DIRECTORY "${SRC}/${layer}")
    continue()
  endif()
  if(NOT DEFINED rank_${layer})
    string(APPEND errors "\n  src/${layer}: a folder with no place in the layer table (add it to check_layers.cmake)")
    continue()
  endif()
  file(GLOB_RECURSE files "${SRC}/${layer}/*.cpp" "${SRC}/${layer}/*.hpp" "${SRC}/${layer}/*.h")
  foreach(f IN LISTS files)
    math(EXPR files_checked "${files_checked} + 1")
    file(STRINGS "${f}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"][a-z_]+/")
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*[<\"]([a-z_]+)/.*" "\\1" target "${line}")
      if(NOT DEFINED rank_${target} OR target STREQUAL layer)
        continue()  # a system header (<sys/...>), or the file's own layer
      endif()
      if(NOT rank_${target} LESS rank_${layer})
        file(RELATIVE_PATH rel "${SRC}" "${f}")
        string(APPEND errors "\n  ${rel}: ${line}  (${layer}, rank ${rank_${layer}}, may not include ${target}, rank ${rank_${target}})")
      endif()
    endforeach()
  endforeach()
endforeach()
if(files_checked EQUAL 0)
  message(FATAL_ERROR "no source files under ${SRC}")
endif()
if(errors)
  message(FATAL_ERROR "includes against the layer order base -> core -> {io, viz} -> scene -> compose -> {render, golden, gltf} -> run -> app -> bench:${errors}")
endif()
message(STATUS "layers: ${files_checked} files, every include points down")
