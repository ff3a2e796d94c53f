/* The pyramid of base 40 (820 boxes) stands for 10 s on its own (no sleeping): its own program,
 * because it is the slowest of the world's tests (about 0.7 s optimized, longer under the
 * sanitizers). */
#include "../test.h"

#include <collide/collide.h>

#include "../world2_test_scenes.h"

/* The soft contacts compress the 40 rows by about 12 centimetres within the first second. */
static void TestPyramid40Stands(void)
{
	CheckPyramidStands(40, CD_R(0.15), 2370);
}

int main(void)
{
	TEST_RUN(TestPyramid40Stands);
	return TEST_SUMMARY();
}
