/* Internal: 3D vectors in double whatever cdReal is, for the triangle queries (closest point,
 * ray cast) that need more than float precision on thin triangles: products of float inputs are
 * exact in double. In the double build they are plain cdReal vectors. */
#ifndef COLLIDE_WIDE3_H
#define COLLIDE_WIDE3_H

#include "collide/math3.h"

typedef struct WideVec
{
	double x, y, z;
} WideVec;

static inline WideVec Widen(cd3Vec v)
{
	WideVec w = {(double)v.x, (double)v.y, (double)v.z};
	return w;
}

static inline cd3Vec Narrow(WideVec w)
{
	return cd3MakeVec((cdReal)w.x, (cdReal)w.y, (cdReal)w.z);
}

static inline WideVec WideSub(WideVec a, WideVec b)
{
	WideVec c = {a.x - b.x, a.y - b.y, a.z - b.z};
	return c;
}

static inline WideVec WideMulAdd(WideVec a, double s, WideVec b)
{
	WideVec c = {a.x + s * b.x, a.y + s * b.y, a.z + s * b.z};
	return c;
}

static inline WideVec WideScale(double s, WideVec a)
{
	WideVec c = {s * a.x, s * a.y, s * a.z};
	return c;
}

static inline double WideDot(WideVec a, WideVec b)
{
	return a.x * b.x + a.y * b.y + a.z * b.z;
}

static inline WideVec WideCross(WideVec a, WideVec b)
{
	WideVec c = {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
	return c;
}

static inline double WideMaxAbs(WideVec v)
{
	double x = v.x < 0.0 ? -v.x : v.x, y = v.y < 0.0 ? -v.y : v.y, z = v.z < 0.0 ? -v.z : v.z;
	return x > y ? (x > z ? x : z) : (y > z ? y : z);
}

/* The face normal ab x ac, computed as the cross product of the two shorter edges (ab x ac =
 * ab x bc = ac x bc): they meet at the largest angle, so the product does not cancel. On a needle,
 * ab x ac of its two long, nearly parallel edges keeps only epsilon / sin(angle) of relative
 * accuracy, which in the double build tilted the plane enough to move the projection of points
 * on a long edge by 6e-9 of the triangle's size. A short edge's vector is exact (its end points
 * are close), and so is its product with a long edge, up to one rounding. */
static inline WideVec WideTriangleNormal(WideVec ab, WideVec ac, WideVec bc)
{
	double abab = WideDot(ab, ab), acac = WideDot(ac, ac), bcbc = WideDot(bc, bc);
	if (bcbc >= abab && bcbc >= acac)
	{
		return WideCross(ab, ac);
	}
	return acac >= abab ? WideCross(ab, bc) : WideCross(ac, bc);
}

#endif
