/* hello3d: the 3D collision queries in one page. A convex hull (a cylinder) stands on a box, a
 * sphere hangs above: overlap, distance, a ray cast and the contact manifold (world space, and the
 * local-frame form a physics step uses). Build: cc hello3d.c $(pkg-config --cflags --libs collide).
 * Exit code 0 when every answer is the expected one. */
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
	/* A floor box (top face at y = 0) and a cylinder hull of half height 0.5 standing on it, sunk
	 * 0.02 into it. Hulls are built once and shared by every shape that places them. */
	cd3Box floor = {cd3MakeVec(CD_R(0.0), CD_R(-0.5), CD_R(0.0)), cd3MakeVec(CD_R(5.0), CD_R(0.5), CD_R(5.0)),
					CD3_QUAT_IDENTITY};
	cd3Hull* cylinder = NULL;
	cdResult r = cd3MakeCylinderHull(CD_R(0.5), CD_R(0.4), 16, &cylinder);
	if (r != CD_OK)
	{
		printf("cd3MakeCylinderHull: %s\n", cdGetResultString(r));
		return 1;
	}
	/* The cylinder's axis is y: standing upright, turned a little about its axis. */
	cd3Transform standing = {cd3MakeVec(CD_R(0.0), CD_R(0.48), CD_R(0.0)),
							 cd3MakeQuatAxisAngle(cd3MakeVec(CD_R(0.0), CD_R(1.0), CD_R(0.0)), CD_R(0.3))};
	cd3Sphere ball = {cd3MakeVec(CD_R(0.0), CD_R(3.0), CD_R(0.0)), CD_R(0.5)};

	cd3Shape sFloor = cd3MakeBoxShape(floor), sCylinder = cd3MakeHullShape(cylinder, standing);
	cd3Shape sBall = cd3MakeSphereShape(ball);

	Expect(cd3Overlap(&sFloor, &sCylinder), "cylinder overlaps the floor");
	Expect(!cd3Overlap(&sBall, &sCylinder), "ball is above the cylinder");

	cd3ClosestPoints d = cd3Distance(&sBall, &sCylinder);
	printf("ball to cylinder: distance %.3f\n", (double)d.distance);
	Expect(cdAbs(d.distance - CD_R(1.52)) < CD_R(1e-3), "ball is 1.52 above the cylinder");

	cd3Ray ray = {cd3MakeVec(CD_R(0.0), CD_R(10.0), CD_R(0.0)),
				  cd3MakeVec(CD_R(0.0), CD_R(-20.0), CD_R(0.0))};
	cd3RayHit hit;
	bool hitCylinder = cd3Raycast(&sCylinder, ray, &hit);
	printf("ray hits the cylinder at y = %.3f, normal (%.1f, %.1f, %.1f)\n", (double)hit.point.y,
		   (double)hit.normal.x, (double)hit.normal.y, (double)hit.normal.z);
	Expect(hitCylinder && cdAbs(hit.point.y - CD_R(0.98)) < CD_R(1e-3), "ray hits the top of the cylinder");

	/* Floor against cylinder: the cylinder's bottom face clipped against the floor, at most 4
	 * points, 0.02 deep. */
	cdReal speculative = CD_SPECULATIVE_DISTANCE;
	cd3Manifold m = cd3Collide(&sFloor, &sCylinder, speculative);
	printf("floor-cylinder manifold: %d points, normal (%.1f, %.1f, %.1f)\n", m.pointCount,
		   (double)m.normal.x, (double)m.normal.y, (double)m.normal.z);
	for (int i = 0; i < m.pointCount; ++i)
	{
		printf("  point (%.3f, %.3f, %.3f) separation %.4f\n", (double)m.points[i].point.x,
			   (double)m.points[i].point.y, (double)m.points[i].point.z, (double)m.points[i].separation);
	}
	Expect(m.pointCount == 4 && cdAbs(m.points[0].separation + CD_R(0.02)) < CD_R(1e-3),
		   "four contact points");

	/* As a physics step computes it: the floor box and the hull in their body frames, the
	 * cylinder body's transform relative to the floor body, the manifold in the floor's frame. */
	cd3Transform floorBody = {floor.center, CD3_QUAT_IDENTITY};
	cd3Box floorLocal = {CD3_VEC_ZERO, floor.halfExtents, CD3_QUAT_IDENTITY};
	cd3HullShape cylinderLocal = {cylinder, CD3_TRANSFORM_IDENTITY};
	cd3Manifold ml = cd3CollideBoxHullLocal(floorLocal, cylinderLocal,
											cd3InvMulTransforms(floorBody, standing), speculative);
	ml = cd3TransformManifold(floorBody, ml);
	Expect(ml.pointCount == m.pointCount && m.pointCount > 0 &&
			   cdAbs(ml.points[0].separation - m.points[0].separation) < CD_R(1e-4),
		   "local-frame manifold is the same contact");

	cd3DestroyHull(cylinder);
	printf("%s\n", g_failures == 0 ? "hello3d: all answers as expected" : "hello3d: FAILED");
	return g_failures == 0 ? 0 : 1;
}
