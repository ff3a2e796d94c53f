/* The local-frame manifolds of manifold2.h against the world-space ones: the same answer, bit for
 * bit, when B's frame is placed in A's frame by the same transform; within round-off when both
 * bodies move; and more precise far from the origin, where world coordinates lose digits. */
#include "collide/manifold2.h"
#include "random_shapes2.h"
#include "test.h"

#include <math.h>
#include <stdio.h>

/* b placed by xf the way the local forms place it (manifold2.h): points transformed, rotations
 * multiplied, an AABB read as a box. */
static cd2Shape Place(const cd2Shape* b, cd2Transform xf)
{
	cd2Shape s = *b;
	switch (b->type)
	{
		case CD2_SHAPE_CIRCLE:
			s.circle.center = cd2TransformPoint(xf, b->circle.center);
			break;
		case CD2_SHAPE_CAPSULE:
			s.capsule.p1 = cd2TransformPoint(xf, b->capsule.p1);
			s.capsule.p2 = cd2TransformPoint(xf, b->capsule.p2);
			break;
		case CD2_SHAPE_AABB:
			s.type = CD2_SHAPE_BOX;
			s.box.center = cd2TransformPoint(xf, cd2AabbCenter(b->aabb));
			s.box.halfExtents = cd2AabbHalfExtents(b->aabb);
			s.box.rotation = xf.q;
			break;
		case CD2_SHAPE_BOX:
			s.box.center = cd2TransformPoint(xf, b->box.center);
			s.box.rotation = cd2MulRot(xf.q, b->box.rotation);
			break;
		case CD2_SHAPE_POLYGON:
			for (int i = 0; i < b->polygon.count; ++i)
			{
				s.polygon.vertices[i] = cd2TransformPoint(xf, b->polygon.vertices[i]);
				s.polygon.normals[i] = cd2RotateVector(xf.q, b->polygon.normals[i]);
			}
			s.polygon.centroid = cd2TransformPoint(xf, b->polygon.centroid);
			break;
		default:
			s.segment.p1 = cd2TransformPoint(xf, b->segment.p1);
			s.segment.p2 = cd2TransformPoint(xf, b->segment.p2);
			break;
	}
	return s;
}

static cd2Transform RandomTransform(TestRng* rng, double extent)
{
	cd2Transform xf;
	xf.p = RandomVec(rng, extent);
	xf.q = RandomRot(rng);
	return xf;
}

static bool SameBits(cd2Manifold m, cd2Manifold n)
{
	if (m.pointCount != n.pointCount || m.normal.x != n.normal.x || m.normal.y != n.normal.y)
	{
		return false;
	}
	for (int i = 0; i < m.pointCount; ++i)
	{
		if (m.points[i].point.x != n.points[i].point.x || m.points[i].point.y != n.points[i].point.y ||
			m.points[i].separation != n.points[i].separation || m.points[i].id != n.points[i].id)
		{
			return false;
		}
	}
	return true;
}

/* Equal within round-off: the same count and ids, points, separations and normal within tolerance
 * (relative to the coordinates' scale). */
static bool Near(cd2Manifold m, cd2Manifold n, double tolerance)
{
	if (m.pointCount != n.pointCount || cd2Length(cd2Sub(m.normal, n.normal)) > tolerance)
	{
		return false;
	}
	for (int i = 0; i < m.pointCount; ++i)
	{
		if (m.points[i].id != n.points[i].id ||
			cd2Length(cd2Sub(m.points[i].point, n.points[i].point)) > tolerance ||
			fabs((double)m.points[i].separation - (double)n.points[i].separation) > tolerance)
		{
			return false;
		}
	}
	return true;
}

/* The pairs whose local form moves A into B's frame (manifold2.h): equal within round-off. */
static bool MovesA(cd2ShapeType a, cd2ShapeType b)
{
	return b == CD2_SHAPE_POLYGON &&
		   (a == CD2_SHAPE_CIRCLE || a == CD2_SHAPE_CAPSULE || a == CD2_SHAPE_SEGMENT);
}

/* The typed pair function of (a, b) in both forms, when a and b are in canonical order and have
 * one (AABBs and boxes only go through cd2Collide). Returns false when there is none. */
static bool TypedPair(const cd2Shape* a, const cd2Shape* b, cd2Transform xf, cdReal d, cd2Manifold* local,
					  cd2Manifold* world)
{
	cd2Shape w = Place(b, xf);
	cd2ShapeType ta = a->type, tb = b->type;
#define PAIR(TA, TB, F, argA, argB, argW)                                                                    \
	if (ta == TA && tb == TB)                                                                                \
	{                                                                                                        \
		*local = F##Local(argA, argB, xf, d);                                                                \
		*world = F(argA, argW, d);                                                                           \
		return true;                                                                                         \
	}
	PAIR(CD2_SHAPE_CIRCLE, CD2_SHAPE_CIRCLE, cd2CollideCircleCircle, a->circle, b->circle, w.circle)
	PAIR(CD2_SHAPE_CIRCLE, CD2_SHAPE_CAPSULE, cd2CollideCircleCapsule, a->circle, b->capsule, w.capsule)
	PAIR(CD2_SHAPE_CIRCLE, CD2_SHAPE_POLYGON, cd2CollideCirclePolygon, a->circle, &b->polygon, &w.polygon)
	PAIR(CD2_SHAPE_CIRCLE, CD2_SHAPE_SEGMENT, cd2CollideCircleSegment, a->circle, b->segment, w.segment)
	PAIR(CD2_SHAPE_CAPSULE, CD2_SHAPE_CAPSULE, cd2CollideCapsuleCapsule, a->capsule, b->capsule, w.capsule)
	PAIR(CD2_SHAPE_CAPSULE, CD2_SHAPE_POLYGON, cd2CollideCapsulePolygon, a->capsule, &b->polygon, &w.polygon)
	PAIR(CD2_SHAPE_CAPSULE, CD2_SHAPE_SEGMENT, cd2CollideCapsuleSegment, a->capsule, b->segment, w.segment)
	PAIR(CD2_SHAPE_POLYGON, CD2_SHAPE_POLYGON, cd2CollidePolygonPolygon, &a->polygon, &b->polygon, &w.polygon)
	PAIR(CD2_SHAPE_POLYGON, CD2_SHAPE_SEGMENT, cd2CollidePolygonSegment, &a->polygon, b->segment, w.segment)
	PAIR(CD2_SHAPE_SEGMENT, CD2_SHAPE_SEGMENT, cd2CollideSegmentSegment, a->segment, b->segment, w.segment)
#undef PAIR
	return false;
}

/* B placed in A's frame: the local form is the world form on the placed shape, bit for bit, for
 * the generic dispatcher (both orders) and every typed pair function; within 1e-6 relative (the
 * shapes reach 8 from the origin) for the pairs that move A into the polygon's frame. */
static void TestSameAsWorldForm(void)
{
	TestRng rng = TestRngMake(0x10ca1u);
	int typed = 0;
	for (int ta = 0; ta < CD2_SHAPE_TYPE_COUNT; ++ta)
	{
		for (int tb = 0; tb < CD2_SHAPE_TYPE_COUNT; ++tb)
		{
			for (int i = 0; i < 200; ++i)
			{
				cd2Shape a = RandomShape(&rng, (cd2ShapeType)ta);
				cd2Shape b = RandomShape(&rng, (cd2ShapeType)tb);
				cd2Transform xf = RandomTransform(&rng, 2.0);
				cdReal d = TestRngInt(&rng, 2) == 0 ? CD_R(0.0) : RandomReal(&rng, 0.0, 0.5);
				cd2Shape w = Place(&b, xf);
				cd2Manifold local = cd2CollideLocal(&a, &b, xf, d);
				cd2Manifold world = cd2Collide(&a, &w, d);
				bool exact = !MovesA(a.type, b.type);
				TEST_CHECKF(exact ? SameBits(local, world) : Near(local, world, 8e-6),
							"%s-%s case %d: %d vs %d points", TypeName(a.type), TypeName(b.type), i,
							local.pointCount, world.pointCount);
				cd2Manifold tl, tw;
				if (TypedPair(&a, &b, xf, d, &tl, &tw))
				{
					++typed;
					TEST_CHECKF(exact ? SameBits(tl, tw) : Near(tl, tw, 8e-6), "typed %s-%s case %d",
								TypeName(a.type), TypeName(b.type), i);
				}
			}
		}
	}
	TEST_CHECK(typed == 10 * 200);

	/* Chain segments: A is the chain segment, as in the world form. */
	for (int i = 0; i < 500; ++i)
	{
		cd2ChainSegment c;
		c.p1 = RandomVec(&rng, 2.0);
		c.p2 = cd2Add(c.p1, cd2MakeVec(-RandomReal(&rng, 0.5, 3.0), RandomReal(&rng, -0.5, 0.5)));
		c.ghost1 = cd2Add(c.p1, cd2MakeVec(RandomReal(&rng, 0.5, 2.0), RandomReal(&rng, -1.0, 1.0)));
		c.ghost2 = cd2Add(c.p2, cd2MakeVec(-RandomReal(&rng, 0.5, 2.0), RandomReal(&rng, -1.0, 1.0)));
		cd2Transform xf = RandomTransform(&rng, 2.0);
		cdReal d = RandomReal(&rng, 0.0, 0.3);
		cd2Shape circle = RandomShape(&rng, CD2_SHAPE_CIRCLE);
		cd2Shape capsule = RandomShape(&rng, CD2_SHAPE_CAPSULE);
		cd2Shape polygon = RandomShape(&rng, CD2_SHAPE_POLYGON);
		cd2Shape wc = Place(&circle, xf), wk = Place(&capsule, xf), wp = Place(&polygon, xf);
		TEST_CHECK(SameBits(cd2CollideChainSegmentCircleLocal(&c, circle.circle, xf, d),
							cd2CollideChainSegmentCircle(&c, wc.circle, d)));
		TEST_CHECK(SameBits(cd2CollideChainSegmentCapsuleLocal(&c, capsule.capsule, xf, d),
							cd2CollideChainSegmentCapsule(&c, wk.capsule, d)));
		TEST_CHECK(Near(cd2CollideChainSegmentPolygonLocal(&c, &polygon.polygon, xf, d),
						cd2CollideChainSegmentPolygon(&c, &wp.polygon, d), 8e-6));
	}
}

/* Both bodies moved: the world form on the two placed shapes against the local form mapped to the
 * world. Equal within 1e-6 relative to the coordinates, with
 * the same points and feature ids except at the rare near ties where one of two features wins by
 * round-off (at most 1% of the pairs). */
static void TestMovedBodies(void)
{
	TestRng rng = TestRngMake(0x10ca2u);
	int cases = 0, ties = 0;
	double worst = 0.0;
	double tolerance = 1e-6;
	for (int ta = 0; ta < CD2_SHAPE_TYPE_COUNT; ++ta)
	{
		for (int tb = 0; tb < CD2_SHAPE_TYPE_COUNT; ++tb)
		{
			for (int i = 0; i < 200; ++i)
			{
				cd2Shape a = RandomShape(&rng, (cd2ShapeType)ta);
				cd2Shape b = RandomShape(&rng, (cd2ShapeType)tb);
				cd2Transform xfA = RandomTransform(&rng, 10.0);
				cd2Transform xfRel = RandomTransform(&rng, 2.0);
				cd2Transform xfB = cd2MulTransforms(xfA, xfRel);
				cdReal d = RandomReal(&rng, 0.0, 0.3);
				cd2Shape wa = Place(&a, xfA), wb = Place(&b, xfB);
				cd2Manifold world = cd2Collide(&wa, &wb, d);
				cd2Manifold local = cd2TransformManifold(xfA, cd2CollideLocal(&a, &b, xfRel, d));
				++cases;
				bool same = world.pointCount == local.pointCount;
				for (int k = 0; same && k < world.pointCount; ++k)
				{
					same = world.points[k].id == local.points[k].id;
				}
				if (!same)
				{
					++ties;
					continue;
				}
				double scale = 12.0 + 10.0 * sqrt(2.0); /* coordinates up to |xfA.p| + shape extents */
				for (int k = 0; k < world.pointCount; ++k)
				{
					double e = fmax(fabs((double)world.points[k].point.x - (double)local.points[k].point.x),
									fabs((double)world.points[k].point.y - (double)local.points[k].point.y));
					e = fmax(e,
							 fabs((double)world.points[k].separation - (double)local.points[k].separation));
					worst = fmax(worst, e / scale);
				}
				if (world.pointCount > 0)
				{
					double e = cd2Length(cd2Sub(world.normal, local.normal));
					/* The normal of a short feature may turn by more than the coordinates' round-off:
					 * points and separations above are what a solver uses. */
					TEST_CHECKF(e < 1e-2, "%s-%s case %d normal differs by %g", TypeName(a.type),
								TypeName(b.type), i, e);
				}
			}
		}
	}
	printf("moved bodies: %d pairs, %d near ties, worst relative difference %.3g (tolerance %.3g)\n", cases,
		   ties, worst, tolerance);
	TEST_CHECKF(ties * 100 <= cases, "%d of %d pairs differ in points or ids", ties, cases);
	TEST_CHECKF(worst <= tolerance, "worst %g", worst);
}

/* Far from the origin: two bodies translated to coordinates around `far`, with shapes in their own
 * frames and a known gap. The local form, fed the relative transform the solver computes
 * (cd2InvMulTransforms of the body transforms, exact for nearby translations), reports the gap to
 * round-off of the shapes' own size; the world form loses the digits of the coordinates. */
static void TestFarFromOrigin(void)
{
	TestRng rng = TestRngMake(0x10ca3u);
	double worstLocal = 0.0, worstWorld = 0.0;
	for (int i = 0; i < 400; ++i)
	{
		double far = TestRngRange(&rng, 1.0e4, 1.0e5);
		cd2Transform xfA = {cd2MakeVec((cdReal)far, (cdReal)(-far * 0.7)), cd2MakeRot(CD_R(0.0))};
		cdReal gap = RandomReal(&rng, 0.001, 0.05);
		cdReal h = RandomReal(&rng, 0.2, 1.0);
		cdReal wB = RandomReal(&rng, 0.2, 1.0);
		/* B above A by h + gap + its own half height; computed in the solver's way. */
		cd2Transform xfB = {cd2Add(xfA.p, cd2MakeVec(RandomReal(&rng, -0.1, 0.1), h + gap + wB)),
							cd2MakeRot(CD_R(0.0))};
		cd2Transform xfRel = cd2InvMulTransforms(xfA, xfB);
		cdReal trueGap = (xfB.p.y - xfA.p.y) - h - wB; /* the gap of the bodies as stored */
		cd2Shape a, b;
		a.type = CD2_SHAPE_POLYGON;
		b.type = TestRngInt(&rng, 2) == 0 ? CD2_SHAPE_POLYGON : CD2_SHAPE_CIRCLE;
		TEST_CHECK(cd2MakeBoxPolygon((cd2Box){cd2MakeVec(CD_R(0.0), CD_R(0.0)), cd2MakeVec(CD_R(2.0), h),
											  cd2MakeRot(CD_R(0.0))},
									 &a.polygon) == CD_OK);
		if (b.type == CD2_SHAPE_POLYGON)
		{
			TEST_CHECK(cd2MakeBoxPolygon((cd2Box){cd2MakeVec(CD_R(0.0), CD_R(0.0)), cd2MakeVec(CD_R(0.5), wB),
												  cd2MakeRot(CD_R(0.0))},
										 &b.polygon) == CD_OK);
		}
		else
		{
			b.circle.center = cd2MakeVec(CD_R(0.0), CD_R(0.0));
			b.circle.radius = wB;
		}
		cd2Manifold local = cd2CollideLocal(&a, &b, xfRel, CD_R(0.1));
		cd2Shape wa = Place(&a, xfA), wb = Place(&b, xfB);
		cd2Manifold world = cd2Collide(&wa, &wb, CD_R(0.1));
		TEST_CHECKF(local.pointCount == (b.type == CD2_SHAPE_POLYGON ? 2 : 1), "case %d: %d points", i,
					local.pointCount);
		for (int k = 0; k < local.pointCount; ++k)
		{
			worstLocal = fmax(worstLocal, fabs((double)local.points[k].separation - (double)trueGap));
		}
		for (int k = 0; k < world.pointCount; ++k)
		{
			worstWorld = fmax(worstWorld, fabs((double)world.points[k].separation - (double)trueGap));
		}
	}
	printf("far from the origin: worst gap error local %.3g, world %.3g\n", worstLocal, worstWorld);
	/* Round-off of the shapes' own coordinates (size ~ 3): a few ulps at 3, not at 1e5. */
	TEST_CHECKF(worstLocal <= 16.0 * (double)CD_REAL_EPSILON * 3.0, "local error %g", worstLocal);
	TEST_CHECK(worstLocal <= worstWorld || worstWorld <= 16.0 * (double)CD_REAL_EPSILON * 3.0);
}

/* The polygons of the centre tests: every 16th trial a square around the origin (a centre at the
 * origin is equally far inside all edges), else a random one, rounded one time in three. */
static cd2Polygon CentreTestPolygon(TestRng* rng, int trial)
{
	cd2Polygon polygon;
	if (trial % 16 == 0)
	{
		cdReal h = RandomReal(rng, 0.1, 2.0);
		cd2Vec corners[4] = {{-h, -h}, {h, -h}, {h, h}, {-h, h}};
		TEST_CHECK(cd2MakePolygon(corners, 4, &polygon) == CD_OK);
	}
	else
	{
		polygon = RandomPolygon(rng, RandomVec(rng, 0.3));
		polygon.radius = TestRngInt(rng, 3) == 0 ? RandomReal(rng, 0.0, 0.2) : CD_R(0.0);
	}
	return polygon;
}

/* A circle centre's target in the polygon's frame, aimed by the trial at every feature: exactly on
 * a vertex, near one, on an edge, near an edge inside or out, the origin (trial % 16 == 4: the
 * square's centre) or the centroid, far away, near by. */
static cd2Vec CentreTestTarget(TestRng* rng, const cd2Polygon* polygon, int trial)
{
	int v = TestRngInt(rng, polygon->count);
	cd2Vec vertex = polygon->vertices[v], after = polygon->vertices[(v + 1) % polygon->count];
	switch (trial % 8)
	{
		case 0:
			return vertex;
		case 1:
			return cd2Add(vertex, RandomVec(rng, 0.3));
		case 2:
			return cd2Lerp(vertex, after, RandomReal(rng, 0.0, 1.0));
		case 3:
		{
			cd2Vec onEdge = cd2Lerp(vertex, after, RandomReal(rng, 0.0, 1.0));
			return cd2MulAdd(onEdge, RandomReal(rng, -0.3, 0.6), polygon->normals[v]);
		}
		case 4:
			return trial % 16 == 4 ? CD2_VEC_ZERO : polygon->centroid;
		case 5:
			return RandomVec(rng, 5.0);
		default:
			return RandomVec(rng, 1.5);
	}
}

/* cd2CollideCirclePolygonLocal has its own scan of the polygon's edges (it stops at the first edge
 * the circle is beyond; two edges to a vector and the contact in vector lanes in the float build on
 * SSE2): its manifold must be, bit for bit, the world form's on the circle's centre
 * placed in the polygon's frame as the local form places it (cd2InvTransformPoint), mapped back by
 * xfB. Centres aimed at every feature: near and exactly on vertices, on edges, inside (ties between
 * equal edges included, with the identity transform so that the centre lands exactly), and far
 * away. */
static void TestCirclePolygonScan(void)
{
	TestRng rng = TestRngMake(0x5ca7c1u);
	int contacts = 0, vertexContacts = 0, empty = 0, ties = 0;
	for (int trial = 0; trial < 40000; ++trial)
	{
		cd2Polygon polygon = CentreTestPolygon(&rng, trial);
		bool identity = TestRngInt(&rng, 4) == 0;
		cd2Transform xf = identity ? CD2_TRANSFORM_IDENTITY : RandomTransform(&rng, 10.0);
		/* The centre's target in the polygon's frame (ties: the square's centre, landing exactly). */
		cd2Vec target = CentreTestTarget(&rng, &polygon, trial);
		ties += trial % 16 == 4 && identity;
		cd2Circle circle;
		circle.center = cd2TransformPoint(xf, target);
		circle.radius = RandomSize(&rng, 0.8);
		cdReal speculative = (cdReal)(0.1 * TestRngInt(&rng, 3));
		cd2Manifold local = cd2CollideCirclePolygonLocal(circle, &polygon, xf, speculative);

		cd2Circle placed = circle;
		placed.center = cd2InvTransformPoint(xf, circle.center);
		cd2Manifold world = cd2CollideCirclePolygon(placed, &polygon, speculative);
		cd2Manifold expected = world;
		if (world.pointCount == 1)
		{
			expected.normal = cd2RotateVector(xf.q, world.normal);
			expected.points[0].point = cd2TransformPoint(xf, world.points[0].point);
		}
		TEST_CHECKF(SameBits(local, expected), "trial %d: count %d/%d id %u/%u sep %.9g/%.9g", trial,
					local.pointCount, expected.pointCount, local.points[0].id, expected.points[0].id,
					(double)local.points[0].separation, (double)expected.points[0].separation);
		contacts += local.pointCount;
		vertexContacts += local.pointCount == 1 && (local.points[0].id & 0x100u) != 0u;
		empty += local.pointCount == 0;
	}
	printf("circle-polygon scan: %d contacts (%d at vertices), %d empty, %d tie cases\n", contacts,
		   vertexContacts, empty, ties);
	/* Every kind of answer was met. */
	TEST_CHECK(contacts > 5000 && vertexContacts > 1000 && empty > 5000 && ties > 100);
}

/* The polygon-first forms. cd2CollidePolygonCircle against cd2CollideCirclePolygon with the shapes
 * swapped: the same points, separations and ids bit for bit, the normal negated (manifold2.h).
 * cd2CollidePolygonCircleLocal against cd2CollidePolygonCircle on the circle placed by
 * cd2TransformPoint: bit for bit (the local-form contract), and cd2CollideLocal on the tagged
 * shapes gives the same bits. Against the circle-first local form with the inverse transform
 * (which takes the centre back into the polygon's frame and maps the contact into the circle's):
 * the same contact within round-off with the opposite normal, the same ids except where two
 * features tie within round-off. Centres aimed at every feature (on and near vertices, on edges,
 * inside, far away), circles centred on their body or not, and exact transforms (the identity,
 * quarter turns, zero and negative-zero translations) as well as random ones. */
static cd2Transform InverseOf(cd2Transform xf)
{
	cd2Transform inv;
	inv.q.c = xf.q.c;
	inv.q.s = -xf.q.s;
	inv.p = cd2Neg(cd2InvRotateVector(xf.q, xf.p));
	return inv;
}

static void TestPolygonCircle(void)
{
	TestRng rng = TestRngMake(0x9c1cu);
	int contacts = 0, vertexContacts = 0, empty = 0, near = 0, mismatches = 0, ties = 0, exactTransforms = 0;
	int trials = 40000;
	for (int trial = 0; trial < trials; ++trial)
	{
		cd2Polygon polygon = CentreTestPolygon(&rng, trial);
		/* xf: the circle's body frame in the polygon's. */
		cd2Transform xf;
		int kind = TestRngInt(&rng, 8);
		if (kind < 3)
		{
			/* Exact: a quarter turn (identity included), a translation with zero or negative-zero
			 * components or none. */
			static const cdReal turns[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
			int turn = TestRngInt(&rng, 4);
			xf.q.c = turns[turn][0];
			xf.q.s = turns[turn][1];
			xf.p = kind == 0 ? CD2_VEC_ZERO : RandomVec(&rng, 3.0);
			if (kind == 1)
			{
				xf.p.x = TestRngInt(&rng, 2) == 0 ? CD_R(0.0) : -CD_R(0.0);
			}
			++exactTransforms;
		}
		else
		{
			xf = RandomTransform(&rng, 10.0);
		}
		/* The centre's target in the polygon's frame. */
		cd2Vec target = CentreTestTarget(&rng, &polygon, trial);
		/* The circle in its body's frame: centred on the body (the common case) or not, placed so
		 * that its centre lands on the target. */
		cd2Circle circle;
		circle.radius = RandomSize(&rng, 0.8);
		circle.center = TestRngInt(&rng, 2) == 0 ? CD2_VEC_ZERO : RandomVec(&rng, 1.0);
		cd2Transform body = xf;
		body.p = cd2Sub(target, cd2RotateVector(xf.q, circle.center));
		if (kind == 0 || (kind == 1 && TestRngInt(&rng, 2) == 0))
		{
			body.p = xf.p; /* keep the exact translation */
		}
		cdReal speculative = (cdReal)(0.1 * TestRngInt(&rng, 3));

		cd2Manifold local = cd2CollidePolygonCircleLocal(&polygon, circle, body, speculative);
		cd2Circle placed = circle;
		placed.center = cd2TransformPoint(body, circle.center);
		cd2Manifold world = cd2CollidePolygonCircle(&polygon, placed, speculative);
		TEST_CHECKF(SameBits(local, world), "trial %d: local %d/%d points, id %u/%u", trial, local.pointCount,
					world.pointCount, local.points[0].id, world.points[0].id);

		/* The world form is the circle-first one with the normal negated. */
		cd2Manifold swapped = cd2CollideCirclePolygon(placed, &polygon, speculative);
		swapped.normal = cd2Neg(swapped.normal);
		TEST_CHECKF(SameBits(world, swapped), "trial %d: polygon-first against circle-first", trial);

		/* The dispatcher on tagged shapes. */
		cd2Shape sa = cd2MakePolygonShape(&polygon);
		cd2Shape sb;
		sb.type = CD2_SHAPE_CIRCLE;
		sb.circle = circle;
		TEST_CHECKF(SameBits(cd2CollideLocal(&sa, &sb, body, speculative), local),
					"trial %d: cd2CollideLocal", trial);

		/* The circle-first local form from the circle's frame, mapped into the polygon's. */
		cd2Manifold first = cd2CollideCirclePolygonLocal(circle, &polygon, InverseOf(body), speculative);
		cd2Manifold mapped = cd2TransformManifold(body, first);
		mapped.normal = cd2Neg(mapped.normal);
		double scale = 1.0 + fabs((double)body.p.x) + fabs((double)body.p.y);
		if (Near(local, mapped, 32.0 * (double)CD_REAL_EPSILON * scale))
		{
			++near;
		}
		else
		{
			/* A tie decided the other way by round-off: the other feature's contact is then just as
			 * deep, so the separations still agree. Centres aimed exactly at a vertex or at the
			 * polygon's centre are ties by construction (two edges, or all, equally near). */
			bool tieByConstruction = trial % 8 == 0 || trial % 8 == 4;
			ties += tieByConstruction;
			mismatches += !tieByConstruction;
			double tie = 64.0 * (double)CD_REAL_EPSILON * scale;
			bool sameDepth = local.pointCount == mapped.pointCount &&
							 (local.pointCount == 0 || fabs((double)local.points[0].separation -
															(double)mapped.points[0].separation) <= tie);
			/* Or at the speculative limit, where one form keeps the contact and the other drops it. */
			bool atLimit = (local.pointCount == 1 &&
							fabs((double)local.points[0].separation - (double)speculative) <= tie) ||
						   (mapped.pointCount == 1 &&
							fabs((double)mapped.points[0].separation - (double)speculative) <= tie);
			TEST_CHECKF(sameDepth || atLimit,
						"trial %d: circle-first %d points sep %.9g, polygon-first %d sep %.9g", trial,
						mapped.pointCount, (double)mapped.points[0].separation, local.pointCount,
						(double)local.points[0].separation);
		}

		if (local.pointCount == 1)
		{
			/* The reported normal and depth: the centre lies along the normal at the radius plus
			 * the separation (plus the polygon's radius) from A's surface point. */
			TEST_CHECK(isfinite((double)local.normal.x) && isfinite((double)local.normal.y));
			TEST_CHECK_NEAR((double)cd2Length(local.normal), 1.0, 1e-5);
		}
		contacts += local.pointCount;
		vertexContacts += local.pointCount == 1 && (local.points[0].id & 0x100u) != 0u;
		empty += local.pointCount == 0;
	}
	printf("polygon-circle: %d contacts (%d at vertices), %d empty, %d exact transforms; circle-first "
		   "form within round-off on %d, a tie by construction on %d, other differences %d\n",
		   contacts, vertexContacts, empty, exactTransforms, near, ties, mismatches);
	TEST_CHECK(contacts > 5000 && vertexContacts > 1000 && empty > 5000 && exactTransforms > 10000);
	TEST_CHECKF(mismatches <= trials / 100, "%d of %d pairs differ beyond round-off", mismatches, trials);
}

/* cd2CollidePolygonCircleBodies, from the two body transforms: bit for bit the world form on the
 * circle's centre placed by cd2TransformPoint(xfB, .) and then cd2InvTransformPoint(xfA, .), and
 * for a circle centred on its body the same values as the local form with the composed transform.
 * Centres aimed at every feature of the polygon; body transforms random, far from the origin, or
 * exact (quarter turns, zero translations, where the centred shortcut does not apply). */
static void TestPolygonCircleBodies(void)
{
	TestRng rng = TestRngMake(0xb0d1e5u);
	int contacts = 0, vertexContacts = 0, empty = 0, centred = 0, exact = 0;
	static const cdReal turns[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
	for (int trial = 0; trial < 40000; ++trial)
	{
		cd2Polygon polygon = CentreTestPolygon(&rng, trial);
		cd2Transform xfA, xfB;
		bool exactFrames = TestRngInt(&rng, 4) == 0;
		if (exactFrames)
		{
			int turnA = TestRngInt(&rng, 4), turnB = TestRngInt(&rng, 4);
			xfA.q.c = turns[turnA][0];
			xfA.q.s = turns[turnA][1];
			xfB.q.c = turns[turnB][0];
			xfB.q.s = turns[turnB][1];
			xfA.p = CD2_VEC_ZERO;
			++exact;
		}
		else
		{
			xfA = RandomTransform(&rng, TestRngInt(&rng, 2) == 0 ? 10.0 : 1000.0);
			xfB.q = RandomTransform(&rng, 1.0).q;
		}
		cd2Circle circle;
		circle.radius = RandomSize(&rng, 0.8);
		bool centredCircle = TestRngInt(&rng, 2) == 0;
		circle.center = centredCircle ? CD2_VEC_ZERO : RandomVec(&rng, 1.0);
		centred += centredCircle;
		/* B's origin placed so that the circle's centre lands on the target (in the polygon's frame);
		 * with exact frames sometimes B's origin at the world origin instead. */
		cd2Vec target = cd2TransformPoint(xfA, CentreTestTarget(&rng, &polygon, trial));
		xfB.p = cd2Sub(target, cd2RotateVector(xfB.q, circle.center));
		if (exactFrames && TestRngInt(&rng, 3) == 0)
		{
			xfB.p = CD2_VEC_ZERO;
		}
		cdReal speculative = (cdReal)(0.1 * TestRngInt(&rng, 3));

		cd2Manifold bodies = cd2CollidePolygonCircleBodies(&polygon, xfA, circle, xfB, speculative);
		cd2Circle placed = circle;
		placed.center = cd2InvTransformPoint(xfA, cd2TransformPoint(xfB, circle.center));
		cd2Manifold world = cd2CollidePolygonCircle(&polygon, placed, speculative);
		TEST_CHECKF(SameBits(bodies, world), "trial %d: bodies %d/%d points, id %u/%u", trial,
					bodies.pointCount, world.pointCount, bodies.points[0].id, world.points[0].id);
		if (centredCircle)
		{
			cd2Manifold local =
				cd2CollidePolygonCircleLocal(&polygon, circle, cd2InvMulTransforms(xfA, xfB), speculative);
			TEST_CHECKF(SameBits(bodies, local), "trial %d: bodies against the local form", trial);
		}
		contacts += bodies.pointCount;
		vertexContacts += bodies.pointCount == 1 && (bodies.points[0].id & 0x100u) != 0u;
		empty += bodies.pointCount == 0;
	}
	printf(
		"polygon-circle from body transforms: %d contacts (%d at vertices), %d empty, %d centred, %d exact\n",
		contacts, vertexContacts, empty, centred, exact);
	TEST_CHECK(contacts > 5000 && vertexContacts > 1000 && empty > 5000 && centred > 10000 && exact > 5000);
}

int main(void)
{
	TEST_RUN(TestSameAsWorldForm);
	TEST_RUN(TestMovedBodies);
	TEST_RUN(TestFarFromOrigin);
	TEST_RUN(TestCirclePolygonScan);
	TEST_RUN(TestPolygonCircle);
	TEST_RUN(TestPolygonCircleBodies);
	return TEST_SUMMARY();
}
