# `rice render` (meshes, a run's every frame and its video, whole and joined from parts, the path
# tracer), `rice figure 13`, `rice study cdrf`, `translucency`, `render` and `path-depth` end to end at toy sizes: each writes its files;
# the same seed renders the same EXR twice; two crops merged are the whole frame, byte for byte; a
# missing mesh exits non-zero and leaves no folder.
# Called by CTest with -DRICE=<rice binary> -DOUT=<scratch folder> -DSCENES=<experiments/scenes>.
file(REMOVE_RECURSE "${OUT}")
function(run)
  execute_process(COMMAND "${RICE}" ${ARGN} RESULT_VARIABLE result ERROR_VARIABLE error OUTPUT_QUIET)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "rice ${ARGN} exited with ${result}: ${error}")
  endif()
endfunction()
include("${CMAKE_CURRENT_LIST_DIR}/../common/expect_same_files.cmake")
function(expect_files folder)
  foreach(name ${ARGN})
    if(NOT EXISTS "${folder}/${name}")
      message(FATAL_ERROR "${folder} lacks ${name}")
    endif()
  endforeach()
endfunction()

run(grains --count 2 --out "${OUT}/grains")
foreach(copy a b)
  run(render --meshes "${OUT}/grains" --side-by-side --width 48 --height 24 --spp 4 --out "${OUT}/render_${copy}")
endforeach()
expect_files("${OUT}/render_a" render.png render.exr run_info.txt)
expect_same("${OUT}/render_a" "${OUT}/render_b" "same seed, two renders" render.exr)
run(render --meshes "${OUT}/grains" --side-by-side --integrator path --max-depth 8 --width 24 --height 12 --spp 2
    --out "${OUT}/render_path")
expect_files("${OUT}/render_path" render.png render.exr run_info.txt)
# The frame `whole` rendered again in two crops, merged: the same EXR and PNG, byte for byte.
function(expect_crops_merge whole width height)
  set(args --meshes "${OUT}/grains" --side-by-side --width ${width} --height ${height} ${ARGN})
  math(EXPR split "${width} / 3")
  run(render ${args} --crop 0 0 ${split} ${height} --out "${whole}_left")
  run(render ${args} --crop ${split} 0 ${width} ${height} --out "${whole}_right")
  run(merge-crops "${whole}_left" "${whole}_right" --out "${whole}_merged")
  expect_same("${whole}" "${whole}_merged" "two crops merged" render.exr render.png)
endfunction()
expect_crops_merge("${OUT}/render_a" 48 24 --spp 4)
expect_crops_merge("${OUT}/render_path" 24 12 --integrator path --max-depth 8 --spp 2)
file(STRINGS "${OUT}/render_path/run_info.txt" integrator REGEX "^integrator: path$")
if(NOT integrator)
  message(FATAL_ERROR "render --integrator path: run_info.txt does not say integrator: path")
endif()
# Every frame of a short run, and its video: H.264, yuv420p, one video frame per run frame.
run(run "${SCENES}/drop.toml" --set grains.count=3 --set solver.frames=4 --set render.width=16 --set render.height=16
    --set render.samples_per_pixel=1 --out "${OUT}/run")
run(render --run "${OUT}/run" --every-frame --video --width 32 --height 18 --spp 1 --out "${OUT}/video")
expect_files("${OUT}/video" frame_0001.png frame_0004.png render.mp4 contact_sheet.png run_info.txt)
execute_process(COMMAND ffprobe -v error -select_streams v:0 -count_frames
                        -show_entries stream=codec_name,pix_fmt,nb_read_frames -of csv=p=0 "${OUT}/video/render.mp4"
                OUTPUT_VARIABLE probe OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE probed)
if(NOT probed EQUAL 0 OR NOT probe STREQUAL "h264,yuv420p,4")
  message(FATAL_ERROR "render.mp4: ffprobe says '${probe}' (exit ${probed}), not h264,yuv420p,4")
endif()
# The contact sheet: all four frames (fewer than 12), one row of 32-pixel tiles 4 apart.
execute_process(COMMAND ffprobe -v error -show_entries stream=width,height -of csv=p=0
                        "${OUT}/video/contact_sheet.png" OUTPUT_VARIABLE sheet OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT sheet STREQUAL "140,18")
  message(FATAL_ERROR "contact_sheet.png is '${sheet}' pixels, not 4 tiles of 32 x 18: 140,18")
endif()
# The video in two parts (as separate processes or cluster jobs render it), joined: the same
# frames, video and contact sheet, byte for byte.
run(render --run "${OUT}/run" --every-frame --frames 3 4 --width 32 --height 18 --spp 1 --out "${OUT}/video_part2")
run(render --run "${OUT}/run" --every-frame --frames 1 2 --width 32 --height 18 --spp 1 --out "${OUT}/video_part1")
run(join-video "${OUT}/video_part2" "${OUT}/video_part1" --out "${OUT}/video_joined")
expect_same("${OUT}/video" "${OUT}/video_joined" "a video joined from two parts" frame_0001.png frame_0002.exr
            frame_0003.png frame_0004.exr render.mp4 contact_sheet.png)
execute_process(COMMAND "${RICE}" join-video "${OUT}/video_part1" "${OUT}/video_part1" --out "${OUT}/video_twice"
                RESULT_VARIABLE result OUTPUT_QUIET ERROR_VARIABLE error)
if(result EQUAL 0 OR NOT error MATCHES "frame [12] is in two parts")
  message(FATAL_ERROR "join-video took a part twice: ${error}")
endif()
# The frame-cost study on the short run: a window of a 64 x 36 frame.
run(study frame-cost --run "${OUT}/run" --width 64 --height 36 --window 16 8 --reference-spp 16 --paper-spp 8
    --sobol-spp 1 2 4 --adaptive-errors 0.5 0.2 --adaptive-spp 2 8 --cost-spp 1 --out "${OUT}/frame-cost")
expect_files("${OUT}/frame-cost" frame_cost.csv run_info.txt window_reference_16/render.exr
             window_adaptive_1/render.exr)
file(STRINGS "${OUT}/frame-cost/frame_cost.csv" rows)
list(LENGTH rows count)
if(NOT count EQUAL 11)  # header, the paper's sampling, three Sobol counts, two adaptive, four models
  message(FATAL_ERROR "frame_cost.csv has ${count} lines, not 11")
endif()
file(STRINGS "${OUT}/frame-cost/run_info.txt" adaptive REGEX "^frame_seconds_adaptive_at_equal_error: ")
if(NOT adaptive)
  message(FATAL_ERROR "the frame-cost study's run_info.txt lacks the adaptive renders' equal-error time")
endif()
run(figure 13 --width 120 --height 40 --spp 2 --path-spp 2 --out "${OUT}/figure13")
expect_files("${OUT}/figure13" figure13_cdrf.png figure13_translucent.exr figure13_path.exr figure13.csv run_info.txt)
file(STRINGS "${OUT}/figure13/run_info.txt" delta_e REGEX "^(cdrf|translucent|path)_delta_e_driest_wettest_(lit|shaded): [0-9.e+-]+$")
list(LENGTH delta_e found)
if(NOT found EQUAL 6)
  message(FATAL_ERROR "figure 13's run_info.txt lacks a row's Delta E of the lit and shaded sides")
endif()
run(study cdrf --photons 2000 --grain-photons 2000 --radii-mm 1 2 --soak-minutes 15 120 --out "${OUT}/cdrf")
expect_files("${OUT}/cdrf" cdrf_fit.csv cdrf_profiles.csv grain_profiles.csv run_info.txt)
run(study translucency --quick --out "${OUT}/translucency")
expect_files("${OUT}/translucency" translucency_fit.csv translucency_table.csv run_info.txt)
run(study render --quick --out "${OUT}/render-study")
expect_files("${OUT}/render-study" render_models.csv plate_reference.exr heap_translucent+2.png run_info.txt)
run(study path-depth --quick --out "${OUT}/path-depth")
expect_files("${OUT}/path-depth" path_depth.csv reference.exr reference.png cdrf.png run_info.txt)
file(STRINGS "${OUT}/path-depth/path_depth.csv" rows)
list(LENGTH rows count)
if(NOT count EQUAL 6)  # header, the reference's noise, three depths, the CDRF
  message(FATAL_ERROR "path_depth.csv has ${count} lines, not 6")
endif()

execute_process(COMMAND "${RICE}" render --meshes "${OUT}/no_such_mesh.ply" --out "${OUT}/bad"
                RESULT_VARIABLE result OUTPUT_QUIET ERROR_QUIET)
if(result EQUAL 0 OR EXISTS "${OUT}/bad")
  message(FATAL_ERROR "a missing mesh was accepted or left a folder")
endif()
