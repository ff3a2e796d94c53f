# Runs `collide query examples/seeds.json --svg OUT` and checks the answer for every pair against
# the geometry designed in examples/README.md (worked out by hand there, not taken from a run),
# the per-scene summaries, and that the SVG was written as well-formed XML.
#   -DTOOL=path -DSEEDS=path -DOUT_DIR=dir [-DXMLLINT=path]
include(${CMAKE_CURRENT_LIST_DIR}/table_check.cmake)

file(MAKE_DIRECTORY ${OUT_DIR})
set(svg ${OUT_DIR}/seeds.svg)
file(REMOVE ${svg})
execute_process(COMMAND ${TOOL} query ${SEEDS} --svg ${svg}
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(context "exit: ${status}\nstdout:\n${out}\nstderr:\n${err}")
if(NOT status STREQUAL "0" OR NOT err STREQUAL "")
  message(FATAL_ERROR "expected exit code 0 and nothing on stderr\n${context}")
endif()
table_check_begin("${out}")

# scene, A, B, overlap, distance (a regex; "" when the hand computation is not simple).
# point-in-box: crate [0,2]^3; inside (1,1,1); outside (3,1,1) is 1 beyond the x = 2 face;
# on-face (2,1.5,0.5) lies on that face, and touching counts.
expect_pair(point-in-box crate inside yes "0")
expect_pair(point-in-box crate outside no "1")
expect_pair(point-in-box crate on-face yes "0")
expect_pair(point-in-box inside outside no "2")
expect_pair(point-in-box inside on-face no "1\\.2247") # sqrt(1.5)
expect_pair(point-in-box outside on-face no "1\\.2247") # sqrt(1.5)
# two-boxes: a [0,2]^3, b [1,3]^3, far [4,5]x[0,1]^2, touch [2,3]x[0,1]^2
expect_pair(two-boxes box-a box-b yes "0")
expect_pair(two-boxes box-a box-far no "2")
expect_pair(two-boxes box-a box-touch yes "0") # shares the face x = 2
expect_pair(two-boxes box-b box-far no "1")
expect_pair(two-boxes box-b box-touch yes "0") # shares an edge
expect_pair(two-boxes box-far box-touch no "1")
# sphere-and-box: ball r 1 at 0; crate from x = 1.5; ball-2 r 0.75 at x = 3.5 reaches into the
# crate (x <= 3); tilted: 45 degrees about z at (0,1.9,0), its corner region within 0.911 of 0.
expect_pair(sphere-and-box ball crate no "0\\.5")
expect_pair(sphere-and-box ball ball-2 no "1\\.75")
expect_pair(sphere-and-box ball tilted yes "0")
expect_pair(sphere-and-box crate ball-2 yes "0")
expect_pair(sphere-and-box crate tilted no "")
expect_pair(sphere-and-box ball-2 tilted no "")
# two-spheres: earth r 2 at 0, moon r 1 at x = 3 (touching), comet r 1 at y = 5, probe r 0.5
# at (0.5,0.5,0) inside earth.
expect_pair(two-spheres earth moon yes "0")
expect_pair(two-spheres earth comet no "2")
expect_pair(two-spheres earth probe yes "0")
expect_pair(two-spheres moon comet no "3\\.83(09|1)") # sqrt(34) - 2
expect_pair(two-spheres moon probe no "1\\.049[45]") # sqrt(6.5) - 1.5
expect_pair(two-spheres comet probe no "3\\.027[78]") # sqrt(20.5) - 1.5
# side-scroller: player [2,3]x[1,3] on platform [0,8]x[0,1]; coin r 0.5 at (5,2);
# player-circle r 1 at (2.5,2) rests on the platform; coin-2 r 0.5 at (3.5,2.8) touches the
# player's right side x = 3.
expect_pair(side-scroller player platform yes "0")
expect_pair(side-scroller player coin no "1\\.5")
expect_pair(side-scroller player player-circle yes "0")
expect_pair(side-scroller player coin-2 yes "0")
expect_pair(side-scroller platform coin no "0\\.5")
expect_pair(side-scroller platform player-circle yes "0")
expect_pair(side-scroller platform coin-2 no "1\\.3")
expect_pair(side-scroller coin player-circle no "1")
expect_pair(side-scroller coin coin-2 no "0\\.7") # sqrt(1.5^2 + 0.8^2) - 1
expect_pair(side-scroller player-circle coin-2 yes "0") # sqrt(1.64) < 1.5
# convex-polygons: left-tri x + y <= 2, right-tri x + y >= 3.2: boxes overlap, SAT separates.
expect_pair(convex-polygons left-tri right-tri no "0\\.848[45]") # 1.2 / sqrt(2)
expect_pair(convex-polygons left-tri slab yes "0")
expect_pair(convex-polygons left-tri hexagon no "")
expect_pair(convex-polygons right-tri slab no "0\\.7")
expect_pair(convex-polygons right-tri hexagon no "")
expect_pair(convex-polygons slab hexagon no "")
# more-3d: ground y <= 0; pillar from y = 0 up; ramp at y >= 1 in z = 0; rod crosses the ramp.
expect_pair(more-3d ground pillar yes "0")
expect_pair(more-3d ground ramp no "1")
expect_pair(more-3d ground rod no "1\\.5")
expect_pair(more-3d pillar ramp no "1\\.5")
expect_pair(more-3d pillar rod no "2\\.5")
expect_pair(more-3d ramp rod yes "0")
# more-2d: beam |x| <= 0.5, |y| <= 2 (a box turned 90 degrees); worm from x = 1; laser y = 1;
# marker on the worm's axis.
expect_pair(more-2d beam worm no "0\\.5")
expect_pair(more-2d beam laser yes "0")
expect_pair(more-2d beam marker no "1\\.5")
expect_pair(more-2d worm laser no "1\\.5")
expect_pair(more-2d worm marker yes "0")
expect_pair(more-2d laser marker no "2")
# hulls: tetra is x, y, z >= 0, x + y + z <= 2. drum is the octagonal prism of radius 1 about the
# line x = 1.5, z = 0 (y from 0 to 2; turning it 45 degrees about y maps it onto itself): its
# left edge x = 0.5, z = 0 dips into tetra (e.g. (0.6, 0.5, 0.05) is inside both). pebble r 0.5
# at (-2, 0.5, 0): tetra's face x = 0 is 2 away, drum's left edge 2.5.
expect_pair(hulls tetra drum yes "0")
expect_pair(hulls tetra pebble no "1\\.5")
expect_pair(hulls drum pebble no "2")
# rounded: pad is the box |x| <= 1, |y| <= 0.5 rounded by 0.25 (reaching x = 1.25); ball r 0.85
# at (2,0) reaches x = 1.15 (0.1 deep). corner-ball r 0.1 at (1.3,0.8) lies in the square
# corner the rounding cuts away: 0.3 sqrt(2) - 0.25 - 0.1 = 0.0743 from pad. rounded-tri is
# (3,-1),(5,-1),(4,1) rounded by 0.2; its left edge lies 3/sqrt(5) from ball's centre and
# 5.2/sqrt(5) from corner-ball's; its corner (3,-1) is sqrt(4.25) from pad's corner (1,-0.5).
expect_pair(rounded pad ball yes "0")
expect_pair(rounded pad corner-ball no "0\\.074[23]")
expect_pair(rounded pad rounded-tri no "1\\.611[56]") # sqrt(4.25) - 0.45
expect_pair(rounded ball corner-ball no "0\\.113[01]?") # sqrt(1.13) - 0.95
expect_pair(rounded ball rounded-tri no "0\\.291[67]") # 3 / sqrt(5) - 1.05
expect_pair(rounded corner-ball rounded-tri no "2\\.025[56]") # 5.2 / sqrt(5) - 0.3

expect_line("point-in-box \\(3D\\): 4 shapes, 6 pairs, 2 overlapping")
expect_line("two-boxes \\(3D\\): 4 shapes, 6 pairs, 3 overlapping")
expect_line("sphere-and-box \\(3D\\): 4 shapes, 6 pairs, 2 overlapping")
expect_line("two-spheres \\(3D\\): 4 shapes, 6 pairs, 2 overlapping")
expect_line("side-scroller \\(2D\\): 5 shapes, 10 pairs, 5 overlapping")
expect_line("convex-polygons \\(2D\\): 4 shapes, 6 pairs, 1 overlapping")
expect_line("more-3d \\(3D\\): 4 shapes, 6 pairs, 2 overlapping")
expect_line("more-2d \\(2D\\): 4 shapes, 6 pairs, 2 overlapping")
expect_line("hulls \\(3D\\): 3 shapes, 3 pairs, 1 overlapping")
expect_line("rounded \\(2D\\): 4 shapes, 6 pairs, 1 overlapping")
# The contacts table (cd2Collide within 0.1): pad pushes ball along +x, 0.1 deep, the point midway
# between the surfaces x = 1.25 and 1.15; corner-ball gets a speculative contact along the
# diagonal; the player's box stands on the platform with its two bottom corners.
expect_line("rounded +pad +ball +1 +\\(1, 0\\) +\\(1\\.2, 0\\) +-0\\.1")
expect_line("rounded +pad +corner-ball +1 +\\(0\\.7071, 0\\.7071\\) +\\([0-9.]+, [0-9.]+\\) +0\\.074[23]")
expect_line("side-scroller +player +platform +2 +\\(0, -1\\) +\\(3, 1\\) \\(2, 1\\) +0")
table_check_end(61)

# The picture: one panel per scene, every name as a label, well-formed XML.
if(NOT EXISTS ${svg})
  message(FATAL_ERROR "${svg} was not written\n${context}")
endif()
file(READ ${svg} picture)
if(NOT picture MATCHES "^<svg " OR NOT picture MATCHES "</svg>\n$")
  message(FATAL_ERROR "${svg} does not start with <svg and end with </svg>")
endif()
string(REGEX MATCHALL "<g id=\"scene-[0-9]+\">" panels "${picture}")
list(LENGTH panels panelCount)
if(NOT panelCount EQUAL 10)
  message(FATAL_ERROR "expected 10 scene panels in the SVG, found ${panelCount}")
endif()
foreach(name IN ITEMS crate on-face box-touch tilted comet player-circle coin-2 hexagon ground rod marker
    tetra drum pebble pad corner-ball rounded-tri)
  if(NOT picture MATCHES ">${name}</text>")
    message(FATAL_ERROR "the SVG has no label \"${name}\"")
  endif()
endforeach()
# Rounded shapes are drawn as paths with arcs; hull edges as lines.
if(NOT picture MATCHES "<path d=\"M[^\"]* A[0-9.]+,[0-9.]+ 0 0 0 ")
  message(FATAL_ERROR "the SVG has no rounded outline (a path with arcs)")
endif()
if(XMLLINT)
  execute_process(COMMAND ${XMLLINT} --noout ${svg} RESULT_VARIABLE lint ERROR_VARIABLE lintErr)
  if(NOT lint EQUAL 0)
    message(FATAL_ERROR "xmllint rejects ${svg}:\n${lintErr}")
  endif()
endif()
