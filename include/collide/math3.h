/* collide: 3D math. Vectors, unit quaternions (x, y, z, w), 3x3 matrices and rigid transforms.
 * Everything is inline; right-handed, +y up; a transform rotates, then translates. */
#ifndef COLLIDE_MATH3_H
#define COLLIDE_MATH3_H

#include "collide/base.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cd3Vec
{
	cdReal x, y, z;
} cd3Vec;

/* Unit quaternion: v' = q v q*. Identity is (0, 0, 0, 1). */
typedef struct cd3Quat
{
	cdReal x, y, z, w;
} cd3Quat;

/* Column-major 3x3 matrix. */
typedef struct cd3Mat33
{
	cd3Vec cx, cy, cz;
} cd3Mat33;

/* A rigid transform: x -> q * x + p. */
typedef struct cd3Transform
{
	cd3Vec p;
	cd3Quat q;
} cd3Transform;

#define CD3_VEC_ZERO ((cd3Vec){CD_R(0.0), CD_R(0.0), CD_R(0.0)})
#define CD3_QUAT_IDENTITY ((cd3Quat){CD_R(0.0), CD_R(0.0), CD_R(0.0), CD_R(1.0)})
#define CD3_TRANSFORM_IDENTITY ((cd3Transform){CD3_VEC_ZERO, CD3_QUAT_IDENTITY})

static inline cd3Vec cd3MakeVec(cdReal x, cdReal y, cdReal z)
{
	cd3Vec v = {x, y, z};
	return v;
}

static inline cd3Vec cd3Add(cd3Vec a, cd3Vec b)
{
	return cd3MakeVec(a.x + b.x, a.y + b.y, a.z + b.z);
}

static inline cd3Vec cd3Sub(cd3Vec a, cd3Vec b)
{
	return cd3MakeVec(a.x - b.x, a.y - b.y, a.z - b.z);
}

static inline cd3Vec cd3Neg(cd3Vec a)
{
	return cd3MakeVec(-a.x, -a.y, -a.z);
}

/* s * a */
static inline cd3Vec cd3Scale(cdReal s, cd3Vec a)
{
	return cd3MakeVec(s * a.x, s * a.y, s * a.z);
}

/* a + s * b */
static inline cd3Vec cd3MulAdd(cd3Vec a, cdReal s, cd3Vec b)
{
	return cd3MakeVec(a.x + s * b.x, a.y + s * b.y, a.z + s * b.z);
}

/* a - s * b */
static inline cd3Vec cd3MulSub(cd3Vec a, cdReal s, cd3Vec b)
{
	return cd3MakeVec(a.x - s * b.x, a.y - s * b.y, a.z - s * b.z);
}

/* Component-wise product. */
static inline cd3Vec cd3MulComponents(cd3Vec a, cd3Vec b)
{
	return cd3MakeVec(a.x * b.x, a.y * b.y, a.z * b.z);
}

static inline cdReal cd3Dot(cd3Vec a, cd3Vec b)
{
	return a.x * b.x + a.y * b.y + a.z * b.z;
}

static inline cd3Vec cd3Cross(cd3Vec a, cd3Vec b)
{
	return cd3MakeVec(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

static inline cd3Vec cd3Min(cd3Vec a, cd3Vec b)
{
	return cd3MakeVec(cdMin(a.x, b.x), cdMin(a.y, b.y), cdMin(a.z, b.z));
}

static inline cd3Vec cd3Max(cd3Vec a, cd3Vec b)
{
	return cd3MakeVec(cdMax(a.x, b.x), cdMax(a.y, b.y), cdMax(a.z, b.z));
}

static inline cd3Vec cd3Abs(cd3Vec a)
{
	return cd3MakeVec(cdAbs(a.x), cdAbs(a.y), cdAbs(a.z));
}

static inline cd3Vec cd3Clamp(cd3Vec v, cd3Vec lower, cd3Vec upper)
{
	return cd3MakeVec(cdClamp(v.x, lower.x, upper.x), cdClamp(v.y, lower.y, upper.y),
					  cdClamp(v.z, lower.z, upper.z));
}

/* a + t * (b - a) */
static inline cd3Vec cd3Lerp(cd3Vec a, cd3Vec b, cdReal t)
{
	return cd3MakeVec(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z));
}

static inline cdReal cd3LengthSquared(cd3Vec v)
{
	return v.x * v.x + v.y * v.y + v.z * v.z;
}

static inline cdReal cd3Length(cd3Vec v)
{
	return cdSqrt(v.x * v.x + v.y * v.y + v.z * v.z);
}

static inline cdReal cd3VecDistanceSquared(cd3Vec a, cd3Vec b)
{
	return cd3LengthSquared(cd3Sub(b, a));
}

static inline cdReal cd3VecDistance(cd3Vec a, cd3Vec b)
{
	return cd3Length(cd3Sub(b, a));
}

/* Unit vector along v, or the zero vector when v is (nearly) zero: never NaN. */
static inline cd3Vec cd3Normalize(cd3Vec v)
{
	cdReal length = cd3Length(v);
	if (length < CD_REAL_EPSILON * CD_REAL_EPSILON || !cdIsValidReal(length))
	{
		return CD3_VEC_ZERO;
	}
	return cd3Scale(CD_R(1.0) / length, v);
}

/* Like cd3Normalize, also returning the length. */
static inline cd3Vec cd3GetLengthAndNormalize(cdReal* length, cd3Vec v)
{
	*length = cd3Length(v);
	if (*length < CD_REAL_EPSILON * CD_REAL_EPSILON || !cdIsValidReal(*length))
	{
		return CD3_VEC_ZERO;
	}
	return cd3Scale(CD_R(1.0) / *length, v);
}

static inline bool cd3IsValidVec(cd3Vec v)
{
	return cdIsValidReal(v.x) && cdIsValidReal(v.y) && cdIsValidReal(v.z);
}

static inline bool cd3VecEqual(cd3Vec a, cd3Vec b)
{
	return a.x == b.x && a.y == b.y && a.z == b.z;
}

static inline cdReal cd3GetComponent(cd3Vec v, int axis)
{
	return axis == 0 ? v.x : (axis == 1 ? v.y : v.z);
}

/* A unit vector perpendicular to unit vector n (stable for every direction). */
static inline cd3Vec cd3Perpendicular(cd3Vec n)
{
	cd3Vec other = cdAbs(n.x) < CD_R(0.57735) ? cd3MakeVec(CD_R(1.0), CD_R(0.0), CD_R(0.0))
											  : cd3MakeVec(CD_R(0.0), CD_R(1.0), CD_R(0.0));
	return cd3Normalize(cd3Cross(n, other));
}

/* ---- quaternions -------------------------------------------------------------------------- */

static inline cd3Quat cd3MakeQuat(cdReal x, cdReal y, cdReal z, cdReal w)
{
	cd3Quat q = {x, y, z, w};
	return q;
}

/* Rotation by `radians` about `axis` (normalized here; a zero axis gives the identity). */
static inline cd3Quat cd3MakeQuatAxisAngle(cd3Vec axis, cdReal radians)
{
	cd3Vec unit = cd3Normalize(axis);
	if (cd3LengthSquared(unit) == CD_R(0.0))
	{
		return CD3_QUAT_IDENTITY;
	}
#if CD_DOUBLE
	cdReal s = sin(0.5 * radians), c = cos(0.5 * radians);
#else
	cdReal s = sinf(0.5f * radians), c = cosf(0.5f * radians);
#endif
	return cd3MakeQuat(s * unit.x, s * unit.y, s * unit.z, c);
}

static inline cdReal cd3QuatLengthSquared(cd3Quat q)
{
	return q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
}

/* Unit length within a tolerance of 1e-4 (float) or 1e-9 (double), and finite. */
static inline bool cd3IsValidQuat(cd3Quat q)
{
	if (!cdIsValidReal(q.x) || !cdIsValidReal(q.y) || !cdIsValidReal(q.z) || !cdIsValidReal(q.w))
	{
		return false;
	}
	cdReal lengthSquared = cd3QuatLengthSquared(q);
#if CD_DOUBLE
	return cdAbs(lengthSquared - 1.0) < 1e-9;
#else
	return cdAbs(lengthSquared - 1.0f) < 1e-4f;
#endif
}

/* Restore unit length; a zero or invalid quaternion becomes the identity. */
static inline cd3Quat cd3NormalizeQuat(cd3Quat q)
{
	cdReal length = cdSqrt(cd3QuatLengthSquared(q));
	if (length < CD_REAL_EPSILON || !cdIsValidReal(length))
	{
		return CD3_QUAT_IDENTITY;
	}
	cdReal inv = CD_R(1.0) / length;
	return cd3MakeQuat(inv * q.x, inv * q.y, inv * q.z, inv * q.w);
}

static inline cd3Quat cd3Conjugate(cd3Quat q)
{
	return cd3MakeQuat(-q.x, -q.y, -q.z, q.w);
}

/* q * r: rotate by r, then by q. */
static inline cd3Quat cd3MulQuat(cd3Quat q, cd3Quat r)
{
	return cd3MakeQuat(
		q.w * r.x + q.x * r.w + q.y * r.z - q.z * r.y, q.w * r.y - q.x * r.z + q.y * r.w + q.z * r.x,
		q.w * r.z + q.x * r.y - q.y * r.x + q.z * r.w, q.w * r.w - q.x * r.x - q.y * r.y - q.z * r.z);
}

/* conjugate(q) * r */
static inline cd3Quat cd3InvMulQuat(cd3Quat q, cd3Quat r)
{
	return cd3MulQuat(cd3Conjugate(q), r);
}

/* q v q*, computed as v + 2w(u x v) + 2u x (u x v) with u = (x, y, z). */
static inline cd3Vec cd3RotateVector(cd3Quat q, cd3Vec v)
{
	cd3Vec u = cd3MakeVec(q.x, q.y, q.z);
	cd3Vec t = cd3Scale(CD_R(2.0), cd3Cross(u, v));
	return cd3Add(cd3MulAdd(v, q.w, t), cd3Cross(u, t));
}

/* q* v q */
static inline cd3Vec cd3InvRotateVector(cd3Quat q, cd3Vec v)
{
	return cd3RotateVector(cd3Conjugate(q), v);
}

/* ---- matrices ----------------------------------------------------------------------------- */

static inline cd3Mat33 cd3MakeMatFromQuat(cd3Quat q)
{
	cdReal x2 = q.x + q.x, y2 = q.y + q.y, z2 = q.z + q.z;
	cdReal xx = q.x * x2, xy = q.x * y2, xz = q.x * z2;
	cdReal yy = q.y * y2, yz = q.y * z2, zz = q.z * z2;
	cdReal wx = q.w * x2, wy = q.w * y2, wz = q.w * z2;
	cd3Mat33 m;
	m.cx = cd3MakeVec(CD_R(1.0) - (yy + zz), xy + wz, xz - wy);
	m.cy = cd3MakeVec(xy - wz, CD_R(1.0) - (xx + zz), yz + wx);
	m.cz = cd3MakeVec(xz + wy, yz - wx, CD_R(1.0) - (xx + yy));
	return m;
}

static inline cd3Vec cd3MulMV(cd3Mat33 m, cd3Vec v)
{
	return cd3Add(cd3Add(cd3Scale(v.x, m.cx), cd3Scale(v.y, m.cy)), cd3Scale(v.z, m.cz));
}

/* transpose(m) * v */
static inline cd3Vec cd3MulMTV(cd3Mat33 m, cd3Vec v)
{
	return cd3MakeVec(cd3Dot(m.cx, v), cd3Dot(m.cy, v), cd3Dot(m.cz, v));
}

static inline cd3Mat33 cd3Transpose(cd3Mat33 m)
{
	cd3Mat33 t;
	t.cx = cd3MakeVec(m.cx.x, m.cy.x, m.cz.x);
	t.cy = cd3MakeVec(m.cx.y, m.cy.y, m.cz.y);
	t.cz = cd3MakeVec(m.cx.z, m.cy.z, m.cz.z);
	return t;
}

static inline cd3Mat33 cd3MulMM(cd3Mat33 a, cd3Mat33 b)
{
	cd3Mat33 c;
	c.cx = cd3MulMV(a, b.cx);
	c.cy = cd3MulMV(a, b.cy);
	c.cz = cd3MulMV(a, b.cz);
	return c;
}

/* ---- transforms --------------------------------------------------------------------------- */

static inline cd3Vec cd3TransformPoint(cd3Transform t, cd3Vec p)
{
	return cd3Add(cd3RotateVector(t.q, p), t.p);
}

static inline cd3Vec cd3InvTransformPoint(cd3Transform t, cd3Vec p)
{
	return cd3InvRotateVector(t.q, cd3Sub(p, t.p));
}

/* a * b: apply b, then a. */
static inline cd3Transform cd3MulTransforms(cd3Transform a, cd3Transform b)
{
	cd3Transform c;
	c.q = cd3MulQuat(a.q, b.q);
	c.p = cd3Add(cd3RotateVector(a.q, b.p), a.p);
	return c;
}

/* inverse(a) * b */
static inline cd3Transform cd3InvMulTransforms(cd3Transform a, cd3Transform b)
{
	cd3Transform c;
	c.q = cd3InvMulQuat(a.q, b.q);
	c.p = cd3InvRotateVector(a.q, cd3Sub(b.p, a.p));
	return c;
}

#ifdef __cplusplus
}
#endif

#endif
