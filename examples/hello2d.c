/* hello2d: the 2D collision queries in one page. A box rests on the ground, a ball falls past it:
 * overlap, distance, a ray cast and the contact manifold (world space, and the local-frame form a
 * physics step uses). Build: cc hello2d.c $(pkg-config --cflags --libs collide). Exit code 0 when
 * every answer is the expected one. */
#include "collide/collide.h"

#include <stdio.h>

static int g_failures = 0;

static void Expect(int ok, const char* what)
{
	printf("%-52s %s\n", what, ok ? "ok" : "UNEXPECTED");
	g_failures += !ok;
}

int main(void)
{
	/* The ground: a wide box polygon centred at the origin (top face at y = 0.5). */
	cd2Polygon ground;
	cd2Box groundBox = {cd2MakeVec(CD_R(0.0), CD_R(0.0)), cd2MakeVec(CD_R(10.0), CD_R(0.5)),
						CD2_ROT_IDENTITY};
	if (cd2MakeBoxPolygon(groundBox, &ground) != CD_OK)
	{
		return 1;
	}

	/* A unit box lying on the ground, sunk 0.01 into it. */
	cd2Polygon box;
	cd2Box crate = {cd2MakeVec(CD_R(0.0), CD_R(0.99)), cd2MakeVec(CD_R(0.5), CD_R(0.5)), CD2_ROT_IDENTITY};
	if (cd2MakeBoxPolygon(crate, &box) != CD_OK)
	{
		return 1;
	}
	cd2Circle ball = {cd2MakeVec(CD_R(3.0), CD_R(2.0)), CD_R(0.25)};

	cd2Shape sGround = cd2MakePolygonShape(&ground), sBox = cd2MakePolygonShape(&box);
	cd2Shape sBall = cd2MakeCircleShape(ball);

	/* Overlap tests on tagged shapes (any pair, either order). */
	Expect(cd2Overlap(&sGround, &sBox), "box overlaps ground");
	Expect(!cd2Overlap(&sGround, &sBall), "ball is above the ground");

	/* Distance and closest points. */
	cd2ClosestPoints d = cd2Distance(&sBall, &sGround);
	printf("ball to ground: distance %.3f, closest point on ground (%.2f, %.2f)\n", (double)d.distance,
		   (double)d.pointB.x, (double)d.pointB.y);
	Expect(cdAbs(d.distance - CD_R(1.25)) < CD_R(1e-4), "ball is 1.25 above the ground");

	/* A ray straight down from above the box hits its top face. */
	cd2Ray ray = {cd2MakeVec(CD_R(0.0), CD_R(5.0)), cd2MakeVec(CD_R(0.0), CD_R(-10.0))};
	cd2RayHit hit;
	bool hitBox = cd2Raycast(&sBox, ray, &hit);
	printf("ray hits the box at (%.2f, %.2f), normal (%.1f, %.1f)\n", (double)hit.point.x,
		   (double)hit.point.y, (double)hit.normal.x, (double)hit.normal.y);
	Expect(hitBox && cdAbs(hit.point.y - CD_R(1.49)) < CD_R(1e-4), "ray hits the top of the box");

	/* The contact manifold between ground and box: two points along the bottom face, 0.01 deep. */
	cdReal speculative = CD_SPECULATIVE_DISTANCE;
	cd2Manifold m = cd2Collide(&sGround, &sBox, speculative);
	printf("ground-box manifold: %d points, normal (%.1f, %.1f)\n", m.pointCount, (double)m.normal.x,
		   (double)m.normal.y);
	for (int i = 0; i < m.pointCount; ++i)
	{
		printf("  point (%.3f, %.3f) separation %.4f id %08x\n", (double)m.points[i].point.x,
			   (double)m.points[i].point.y, (double)m.points[i].separation, (unsigned)m.points[i].id);
	}
	Expect(m.pointCount == 2 && cdAbs(m.points[0].separation + CD_R(0.01)) < CD_R(1e-4),
		   "two contact points");

	/* The same contact as a physics step computes it: shapes in body frames, the box body's
	 * transform relative to the ground body, the manifold in the ground's frame. */
	cd2Polygon localBox;
	cd2Box local = {cd2MakeVec(CD_R(0.0), CD_R(0.0)), cd2MakeVec(CD_R(0.5), CD_R(0.5)), CD2_ROT_IDENTITY};
	if (cd2MakeBoxPolygon(local, &localBox) != CD_OK)
	{
		return 1;
	}
	cd2Transform groundBody = CD2_TRANSFORM_IDENTITY;
	cd2Transform boxBody = {cd2MakeVec(CD_R(0.0), CD_R(0.99)), CD2_ROT_IDENTITY};
	cd2Manifold ml = cd2CollidePolygonPolygonLocal(&ground, &localBox,
												   cd2InvMulTransforms(groundBody, boxBody), speculative);
	ml = cd2TransformManifold(groundBody, ml);
	Expect(ml.pointCount == m.pointCount && ml.points[0].id == m.points[0].id &&
			   cdAbs(ml.points[0].separation - m.points[0].separation) < CD_R(1e-5),
		   "local-frame manifold is the same contact");

	printf("%s\n", g_failures == 0 ? "hello2d: all answers as expected" : "hello2d: FAILED");
	return g_failures == 0 ? 0 : 1;
}
