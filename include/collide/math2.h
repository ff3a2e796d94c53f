/* collide: 2D math. Vectors, rotations stored as a cosine/sine pair, 2x2 matrices and rigid
 * transforms. Everything is inline; a transform rotates, then translates. +y is up. */
#ifndef COLLIDE_MATH2_H
#define COLLIDE_MATH2_H

#include "collide/base.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cd2Vec
{
	cdReal x, y;
} cd2Vec;

/* A rotation as the cosine and sine of its angle (unit length: c*c + s*s = 1). */
typedef struct cd2Rot
{
	cdReal c, s;
} cd2Rot;

/* Column-major 2x2 matrix. */
typedef struct cd2Mat22
{
	cd2Vec cx, cy;
} cd2Mat22;

/* A rigid transform: x -> q * x + p. */
typedef struct cd2Transform
{
	cd2Vec p;
	cd2Rot q;
} cd2Transform;

#define CD2_VEC_ZERO ((cd2Vec){CD_R(0.0), CD_R(0.0)})
#define CD2_ROT_IDENTITY ((cd2Rot){CD_R(1.0), CD_R(0.0)})
#define CD2_TRANSFORM_IDENTITY ((cd2Transform){CD2_VEC_ZERO, CD2_ROT_IDENTITY})

static inline cd2Vec cd2MakeVec(cdReal x, cdReal y)
{
	cd2Vec v = {x, y};
	return v;
}

static inline cd2Vec cd2Add(cd2Vec a, cd2Vec b)
{
	return cd2MakeVec(a.x + b.x, a.y + b.y);
}

static inline cd2Vec cd2Sub(cd2Vec a, cd2Vec b)
{
	return cd2MakeVec(a.x - b.x, a.y - b.y);
}

static inline cd2Vec cd2Neg(cd2Vec a)
{
	return cd2MakeVec(-a.x, -a.y);
}

/* s * a */
static inline cd2Vec cd2Scale(cdReal s, cd2Vec a)
{
	return cd2MakeVec(s * a.x, s * a.y);
}

/* a + s * b */
static inline cd2Vec cd2MulAdd(cd2Vec a, cdReal s, cd2Vec b)
{
	return cd2MakeVec(a.x + s * b.x, a.y + s * b.y);
}

/* a - s * b */
static inline cd2Vec cd2MulSub(cd2Vec a, cdReal s, cd2Vec b)
{
	return cd2MakeVec(a.x - s * b.x, a.y - s * b.y);
}

static inline cdReal cd2Dot(cd2Vec a, cd2Vec b)
{
	return a.x * b.x + a.y * b.y;
}

/* z component of the 3D cross product of (a, 0) and (b, 0). */
static inline cdReal cd2Cross(cd2Vec a, cd2Vec b)
{
	return a.x * b.y - a.y * b.x;
}

/* cross(v, s): v rotated clockwise by 90 degrees and scaled. */
static inline cd2Vec cd2CrossVS(cd2Vec v, cdReal s)
{
	return cd2MakeVec(s * v.y, -s * v.x);
}

/* cross(s, v): v rotated counter-clockwise by 90 degrees and scaled. */
static inline cd2Vec cd2CrossSV(cdReal s, cd2Vec v)
{
	return cd2MakeVec(-s * v.y, s * v.x);
}

/* Counter-clockwise perpendicular (-y, x). */
static inline cd2Vec cd2LeftPerp(cd2Vec v)
{
	return cd2MakeVec(-v.y, v.x);
}

/* Clockwise perpendicular (y, -x). */
static inline cd2Vec cd2RightPerp(cd2Vec v)
{
	return cd2MakeVec(v.y, -v.x);
}

static inline cd2Vec cd2Min(cd2Vec a, cd2Vec b)
{
	return cd2MakeVec(cdMin(a.x, b.x), cdMin(a.y, b.y));
}

static inline cd2Vec cd2Max(cd2Vec a, cd2Vec b)
{
	return cd2MakeVec(cdMax(a.x, b.x), cdMax(a.y, b.y));
}

static inline cd2Vec cd2Abs(cd2Vec a)
{
	return cd2MakeVec(cdAbs(a.x), cdAbs(a.y));
}

static inline cd2Vec cd2Clamp(cd2Vec v, cd2Vec lower, cd2Vec upper)
{
	return cd2MakeVec(cdClamp(v.x, lower.x, upper.x), cdClamp(v.y, lower.y, upper.y));
}

/* a + t * (b - a) */
static inline cd2Vec cd2Lerp(cd2Vec a, cd2Vec b, cdReal t)
{
	return cd2MakeVec(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y));
}

static inline cdReal cd2LengthSquared(cd2Vec v)
{
	return v.x * v.x + v.y * v.y;
}

static inline cdReal cd2Length(cd2Vec v)
{
	return cdSqrt(v.x * v.x + v.y * v.y);
}

static inline cdReal cd2VecDistanceSquared(cd2Vec a, cd2Vec b)
{
	return cd2LengthSquared(cd2Sub(b, a));
}

static inline cdReal cd2VecDistance(cd2Vec a, cd2Vec b)
{
	return cd2Length(cd2Sub(b, a));
}

/* Unit vector along v, or the zero vector when v is (nearly) zero: never NaN. */
static inline cd2Vec cd2Normalize(cd2Vec v)
{
	cdReal length = cd2Length(v);
	if (length < CD_REAL_EPSILON * CD_REAL_EPSILON || !cdIsValidReal(length))
	{
		return CD2_VEC_ZERO;
	}
	return cd2Scale(CD_R(1.0) / length, v);
}

/* Like cd2Normalize, also returning the length. */
static inline cd2Vec cd2GetLengthAndNormalize(cdReal* length, cd2Vec v)
{
	*length = cd2Length(v);
	if (*length < CD_REAL_EPSILON * CD_REAL_EPSILON || !cdIsValidReal(*length))
	{
		return CD2_VEC_ZERO;
	}
	return cd2Scale(CD_R(1.0) / *length, v);
}

static inline bool cd2IsValidVec(cd2Vec v)
{
	return cdIsValidReal(v.x) && cdIsValidReal(v.y);
}

static inline bool cd2VecEqual(cd2Vec a, cd2Vec b)
{
	return a.x == b.x && a.y == b.y;
}

/* ---- rotations ---------------------------------------------------------------------------- */

/* Rotation by `radians` counter-clockwise. */
static inline cd2Rot cd2MakeRot(cdReal radians)
{
#if CD_DOUBLE
	cd2Rot q = {cos(radians), sin(radians)};
#else
	cd2Rot q = {cosf(radians), sinf(radians)};
#endif
	return q;
}

static inline cdReal cd2RotGetAngle(cd2Rot q)
{
	return cdAtan2(q.s, q.c);
}

/* Unit length within a relative tolerance of 1e-4 (float) or 1e-9 (double), and finite. */
static inline bool cd2IsValidRot(cd2Rot q)
{
	if (!cdIsValidReal(q.c) || !cdIsValidReal(q.s))
	{
		return false;
	}
	cdReal lengthSquared = q.c * q.c + q.s * q.s;
#if CD_DOUBLE
	return cdAbs(lengthSquared - 1.0) < 1e-9;
#else
	return cdAbs(lengthSquared - 1.0f) < 1e-4f;
#endif
}

/* Restore unit length after accumulated round-off. */
static inline cd2Rot cd2NormalizeRot(cd2Rot q)
{
	cdReal length = cdSqrt(q.c * q.c + q.s * q.s);
	if (length < CD_REAL_EPSILON || !cdIsValidReal(length))
	{
		return CD2_ROT_IDENTITY;
	}
	cd2Rot r = {q.c / length, q.s / length};
	return r;
}

static inline cd2Vec cd2RotateVector(cd2Rot q, cd2Vec v)
{
	return cd2MakeVec(q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y);
}

static inline cd2Vec cd2InvRotateVector(cd2Rot q, cd2Vec v)
{
	return cd2MakeVec(q.c * v.x + q.s * v.y, -q.s * v.x + q.c * v.y);
}

/* q * r: rotate by r, then by q. */
static inline cd2Rot cd2MulRot(cd2Rot q, cd2Rot r)
{
	cd2Rot qr = {q.c * r.c - q.s * r.s, q.s * r.c + q.c * r.s};
	return qr;
}

/* transpose(q) * r */
static inline cd2Rot cd2InvMulRot(cd2Rot q, cd2Rot r)
{
	cd2Rot qr = {q.c * r.c + q.s * r.s, q.c * r.s - q.s * r.c};
	return qr;
}

/* ---- matrices ----------------------------------------------------------------------------- */

static inline cd2Vec cd2MulMV(cd2Mat22 m, cd2Vec v)
{
	return cd2MakeVec(m.cx.x * v.x + m.cy.x * v.y, m.cx.y * v.x + m.cy.y * v.y);
}

/* Solve m * x = b; returns the zero vector when m is singular. */
static inline cd2Vec cd2Solve22(cd2Mat22 m, cd2Vec b)
{
	cdReal det = m.cx.x * m.cy.y - m.cy.x * m.cx.y;
	if (det == CD_R(0.0))
	{
		return CD2_VEC_ZERO;
	}
	cdReal invDet = CD_R(1.0) / det;
	return cd2MakeVec(invDet * (m.cy.y * b.x - m.cy.x * b.y), invDet * (m.cx.x * b.y - m.cx.y * b.x));
}

/* ---- transforms --------------------------------------------------------------------------- */

static inline cd2Vec cd2TransformPoint(cd2Transform t, cd2Vec p)
{
	return cd2Add(cd2RotateVector(t.q, p), t.p);
}

static inline cd2Vec cd2InvTransformPoint(cd2Transform t, cd2Vec p)
{
	return cd2InvRotateVector(t.q, cd2Sub(p, t.p));
}

/* a * b: apply b, then a. */
static inline cd2Transform cd2MulTransforms(cd2Transform a, cd2Transform b)
{
	cd2Transform c;
	c.q = cd2MulRot(a.q, b.q);
	c.p = cd2Add(cd2RotateVector(a.q, b.p), a.p);
	return c;
}

/* inverse(a) * b */
static inline cd2Transform cd2InvMulTransforms(cd2Transform a, cd2Transform b)
{
	cd2Transform c;
	c.q = cd2InvMulRot(a.q, b.q);
	c.p = cd2InvRotateVector(a.q, cd2Sub(b.p, a.p));
	return c;
}

#ifdef __cplusplus
}
#endif

#endif
