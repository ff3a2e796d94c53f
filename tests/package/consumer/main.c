/* A user of the installed collide package: includes the umbrella header, links the library and
 * checks a few answers, the version and that headers and library agree on cdReal. */
#include <collide/collide.h>

#include <stdio.h>

static int g_failures = 0;

static void Check(int condition, const char* what)
{
	if (!condition)
	{
		fprintf(stderr, "consumer: check failed: %s\n", what);
		++g_failures;
	}
}

int main(void)
{
	cdVersion version = cdGetVersion();
	Check(version.major == CD_VERSION_MAJOR && version.minor == CD_VERSION_MINOR &&
			  version.patch == CD_VERSION_PATCH,
		  "cdGetVersion() matches the installed config.h");
	Check(cdGetRealIsDouble() == CD_DOUBLE, "cdGetRealIsDouble() == CD_DOUBLE");
#ifdef CONSUMER_EXPECT_DOUBLE
	Check(CD_DOUBLE == CONSUMER_EXPECT_DOUBLE, "CD_DOUBLE is the precision the package was built with");
#endif

	cd3Sphere a = {{CD_R(0.0), CD_R(0.0), CD_R(0.0)}, CD_R(1.0)};
	cd3Sphere touching = {{CD_R(2.0), CD_R(0.0), CD_R(0.0)}, CD_R(1.0)};
	cd3Sphere apart = {{CD_R(2.5), CD_R(0.0), CD_R(0.0)}, CD_R(1.0)};
	Check(cd3OverlapSphereSphere(a, touching), "touching spheres overlap");
	Check(!cd3OverlapSphereSphere(a, apart), "separated spheres do not overlap");

	cd2Circle c1 = {{CD_R(0.0), CD_R(0.0)}, CD_R(1.0)};
	cd2Circle c2 = {{CD_R(1.5), CD_R(0.0)}, CD_R(1.0)};
	Check(cd2OverlapCircleCircle(c1, c2), "overlapping circles overlap");

	cd2Vec square[4] = {
		{CD_R(0.0), CD_R(0.0)}, {CD_R(1.0), CD_R(1.0)}, {CD_R(1.0), CD_R(0.0)}, {CD_R(0.0), CD_R(1.0)}};
	cd2Polygon polygon;
	Check(cd2MakePolygon(square, 4, &polygon) == CD_OK && polygon.count == 4,
		  "cd2MakePolygon builds a square");

	if (g_failures != 0)
	{
		return 1;
	}
	printf("consumer: collide %d.%d.%d, cdReal = %s: ok\n", version.major, version.minor, version.patch,
		   CD_DOUBLE ? "double" : "float");
	return 0;
}
