# The other spellings of the file format: a file that is one scene (no "scenes" list), comments,
# a clockwise polygon, a 2D box turned by "angle" in radians, a 3D box turned by a quaternion
# "rotation". Expected answers are worked out in the comments.
#   -DTOOL=path -DOUT_DIR=dir
include(${CMAKE_CURRENT_LIST_DIR}/table_check.cmake)
file(MAKE_DIRECTORY ${OUT_DIR})

function(run_tool file)
  execute_process(COMMAND ${TOOL} query ${file} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status STREQUAL "0" OR NOT err STREQUAL "")
    message(FATAL_ERROR "collide query ${file}: exit ${status}\n${out}\n${err}")
  endif()
  set(OUT "${out}" PARENT_SCOPE)
endfunction()

# cw-square [0,2]^2 given clockwise. spinner: half extents (1, 0.25) turned 45 degrees about
# (3,1): its corners are (3,1) + 0.7071 * (x - y, x + y), the leftmost (2.1161, 0.1161), which
# is 0.1161 right of the square. hook: the segment x = 1 from y = 1 to 3 crosses the square.
file(WRITE ${OUT_DIR}/single.json [=[
{
  "comment": "one scene, no list",
  "name": "single",
  "dimension": 2,
  "shapes": [
    { "name": "cw-square", "type": "polygon", "points": [[0, 0], [0, 2], [2, 2], [2, 0]], "comment": "clockwise" },
    { "name": "spinner", "type": "box", "center": [3, 1], "halfExtents": [1, 0.25], "angle": 0.7853981633974483 },
    { "name": "hook", "type": "segment", "p1": [1, 1], "p2": [1, 3] }
  ]
}
]=])
run_tool(${OUT_DIR}/single.json)
table_check_begin("${OUT}")
expect_pair(single cw-square spinner no "0\\.116[12]")
expect_pair(single cw-square hook yes "0")
expect_pair(single spinner hook no "")
expect_line("single \\(2D\\): 3 shapes, 3 pairs, 1 overlapping")
table_check_end(3)

# turned: the cube [-1,1]^3 turned 45 degrees about z (quaternion (0, 0, sin 22.5, cos 22.5)),
# so it reaches x = sqrt(2) = 1.4142 along its edge. near: r 0.6 at x = 2 reaches x = 1.4 < 1.4142;
# far: r 0.5 at y = 3 stays 3 - 0.5 - 1.4142 = 1.0858 above it.
file(WRITE ${OUT_DIR}/rotation.json [=[
{ "scenes": [ { "name": "quaternion", "dimension": 3, "shapes": [
  { "name": "turned", "type": "box", "center": [0, 0, 0], "halfExtents": [1, 1, 1],
    "rotation": [0, 0, 0.38268343236508984, 0.9238795325112867] },
  { "name": "near", "type": "sphere", "center": [2, 0, 0], "radius": 0.6 },
  { "name": "far", "type": "sphere", "center": [0, 3, 0], "radius": 0.5 }
] } ] }
]=])
run_tool(${OUT_DIR}/rotation.json)
table_check_begin("${OUT}")
expect_pair(quaternion turned near yes "0")
expect_pair(quaternion turned far no "1\\.085[789]")
expect_pair(quaternion near far no "")
expect_line("quaternion \\(3D\\): 3 shapes, 3 pairs, 1 overlapping")
table_check_end(3)

# A scene with one shape has no pairs; the tool says so and succeeds.
file(WRITE ${OUT_DIR}/lonely.json [=[{ "dimension": 3, "shapes": [ { "name": "alone", "type": "point", "at": [0, 0, 0] } ] }]=])
run_tool(${OUT_DIR}/lonely.json)
table_check_begin("${OUT}")
expect_line("scene1 \\(3D\\): 1 shape, 0 pairs, 0 overlapping")
table_check_end(0)
