# The gltf_validator test: writes every kind of glTF file Kinema produces (the writer's
# sample scene, the default character, the shared BVH captures converted, the shared glTF
# files re-exported directly and through .kinema) and runs the Khronos glTF validator on
# them. Zero errors required. Prints SKIPPED (CTest's skip pattern for this test) when
# node or the validator is missing; CMake 3.25 has no cmake_language(EXIT).
# Inputs: NODE, MODULES (node_modules with gltf-validator), SCRIPT, KINEMA, TESTS,
# SOURCE_DIR, SHARED_DATA, OUT.
if(NOT NODE OR NOT EXISTS "${MODULES}/gltf-validator/package.json")
  message("SKIPPED: the Khronos glTF validator is not installed (needs node and "
          "`npm install` of tests/tools/gltf_validator/package.json into ${MODULES}/..; .ci/test does it)")
  return()
endif()
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (exit ${rc}): ${ARGN}\n${out}${err}")
  endif()
endfunction()

run(${CMAKE_COMMAND} -E env KINEMA_GLTF_SAMPLE_DIR=${OUT} ${TESTS} --gtest_filter=GltfWriterSamples.*)
run(${KINEMA} convert ${SOURCE_DIR}/assets/default_character.kinema ${OUT}/default_character.gltf)
run(${KINEMA} convert ${SOURCE_DIR}/assets/default_character.kinema ${OUT}/default_character.glb)
if(EXISTS "${SHARED_DATA}")
  file(GLOB bvh_files "${SHARED_DATA}/bvh/*.bvh")
  foreach(f IN LISTS bvh_files)
    get_filename_component(name "${f}" NAME_WE)
    run(${KINEMA} convert ${f} ${OUT}/bvh_${name}.gltf)
    run(${KINEMA} convert ${f} ${OUT}/bvh_${name}.glb)
  endforeach()
  file(GLOB_RECURSE gltf_files "${SHARED_DATA}/gltf/*.gltf" "${SHARED_DATA}/gltf/*.glb")
  foreach(f IN LISTS gltf_files)
    get_filename_component(name "${f}" NAME_WE)
    run(${KINEMA} convert ${f} ${OUT}/gltf_${name}.glb)
    run(${KINEMA} convert ${f} ${OUT}/gltf_${name}.kinema)
    run(${KINEMA} convert ${OUT}/gltf_${name}.kinema ${OUT}/gltf_${name}_via_kinema.gltf)
  endforeach()
  # Issue 23: Fox with its tail made dynamic, baked by `kinema simulate` into glTF and GLB.
  if(EXISTS "${SHARED_DATA}/gltf/Fox.glb")
    file(READ ${OUT}/gltf_Fox.kinema fox)
    string(JSON fox SET "${fox}" simulation
      [=[{"spring_chains": [{"name": "tail", "joints": ["b_Tail01_012", "b_Tail02_013", "b_Tail03_014"],
          "stiffness": 40, "damping": 3, "gravity": [0, -981, 0], "radius": 1}]}]=])
    file(WRITE ${OUT}/fox_tail.kinema "${fox}")
    run(${KINEMA} simulate ${OUT}/fox_tail.kinema --frames 0:40 --out ${OUT}/fox_tail_simulated.gltf)
    run(${KINEMA} simulate ${OUT}/fox_tail.kinema --frames 0:40 --out ${OUT}/fox_tail_simulated.glb)
  endif()
  # Issue 24: a crowd of six CesiumMen, each a skinned character of its own in one file.
  if(EXISTS "${SHARED_DATA}/gltf/CesiumMan.glb")
    file(READ ${OUT}/gltf_CesiumMan.kinema cesium)
    string(JSON cesium SET "${cesium}" simulation
      [=[{"crowds": [{"name": "crowd", "members": 6, "seed": 3, "obstacles": {"spheres": [{"centre": [0, 0, 0], "radius": 1}]}}]}]=])
    file(WRITE ${OUT}/cesium_crowd.kinema "${cesium}")
    run(${KINEMA} simulate ${OUT}/cesium_crowd.kinema --frames 0:20 --out ${OUT}/cesium_crowd.gltf)
    run(${KINEMA} simulate ${OUT}/cesium_crowd.kinema --frames 0:20 --out ${OUT}/cesium_crowd.glb)
  endif()
else()
  message("note: ${SHARED_DATA} is absent; validating the project's own files only")
endif()

file(GLOB written "${OUT}/*.gltf" "${OUT}/*.glb")
list(LENGTH written count)
message("validating ${count} files")
execute_process(COMMAND ${NODE} ${SCRIPT} ${MODULES} ${written} RESULT_VARIABLE rc)
if(rc EQUAL 77)
  return()  # validate_gltf.mjs printed SKIPPED
elseif(NOT rc EQUAL 0)
  message(FATAL_ERROR "the glTF validator found errors (see above)")
endif()
