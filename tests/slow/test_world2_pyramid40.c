/* The pyramid of base 40 (820 boxes) stands for 10 s on its own (no sleeping): its own program,
 * because it is the slowest of the world's tests (about 0.7 s optimized, longer under the
 * sanitizers). */
#include "../test.h"

#include <collide/collide.h>

#include "../world2_test_scenes.h"

/* The soft contacts compress the 40 rows by about 12 centimetres within the first second. */
static void TestPyramid40Stands(void)
{
	/* The top stays within 3 mm of its place sideways: the solver's passes carry no left-right
	 * bias that would sway the pyramid (graph_color.c). */
	cdReal sway = CheckPyramidStands(40, CD_R(0.15), 2370);
	TEST_CHECKF(sway < CD_R(0.003), "the top swayed %g sideways after the first second", (double)sway);
}

int main(void)
{
	TEST_RUN(TestPyramid40Stands);
	return TEST_SUMMARY();
}
