/* collide: ray-cast building blocks shared by the 2D and 3D ray casts (internal, not installed).
 * Both dimensions run the same slab test and the same sphere/circle entry formula; only the
 * vector types differ, so these helpers take plain scalars and arrays. The slab test is written
 * once per dimension through base/dim.h: define CD_DIM before including this header to get
 * cd2RaycastSlabs or cd3RaycastSlabs. */
#ifndef COLLIDE_RAYCAST_COMMON_H
#define COLLIDE_RAYCAST_COMMON_H

#include "collide/base.h"

typedef enum cdSlabResult
{
	CD_SLAB_MISS,
	CD_SLAB_INSIDE, /* the origin lies in the closed box */
	CD_SLAB_HIT
} cdSlabResult;

/* Entry distance of a ray (unit direction) into a ball of radius r, from
 *   along = dot(origin - center, direction),
 *   outside = |origin - center|^2 - r^2 (> 0: the origin is outside),
 *   lineDistanceSquared = squared distance from the center to the ray's line.
 * The discriminant r^2 - lineDistanceSquared avoids the cancellation of the textbook
 * along^2 - outside, and the near root is outside / (-along + sqrt(disc)) (the product of the
 * roots is `outside`), which never subtracts nearly equal numbers. Returns false when the ray
 * moves away, misses the line, or the entry lies beyond maxDistance. *halfChord is
 * sqrt(r^2 - lineDistanceSquared): the entry point is the foot of the center on the line, moved
 * back by it, which gives the normal without the round-off of origin + distance * direction. */
static inline bool cdRayEntryIntoBall(cdReal along, cdReal outside, cdReal radiusSquared,
									  cdReal lineDistanceSquared, cdReal maxDistance, cdReal* distance,
									  cdReal* halfChord)
{
	if (along >= CD_R(0.0))
	{
		return false;
	}
	cdReal disc = radiusSquared - lineDistanceSquared;
	if (disc < CD_R(0.0))
	{
		return false;
	}
	cdReal root = cdSqrt(disc);
	cdReal t = outside / (-along + root);
	if (t > maxDistance)
	{
		return false;
	}
	*distance = t;
	*halfChord = root;
	return true;
}

#endif

/* ---- per dimension: the including file defines CD_DIM (2 or 3) first (base/dim.h) ------------ */
#ifdef CD_DIM
#include "base/dim.h"

/* Slab test (Ericson 5.3.3) of the ray origin + t * translation, t in [0, 1], against the closed
 * box lower <= x <= upper in CD_DIM axes. On CD_SLAB_HIT, *fraction is the entry fraction and
 * *axis the axis whose face the ray enters through (its outward normal is -sign(translation)).
 * Divisions, not multiplications by 1 / translation: a denormal component would make the inverse
 * infinite and 0 * inf a NaN, while (lower - origin) / translation is at worst a signed infinity,
 * which the comparisons handle. Components that are exactly zero never divide. */
static inline cdSlabResult CD_DIM_NAME(RaycastSlabs)(const cdReal* origin, const cdReal* translation,
													 const cdReal* lower, const cdReal* upper,
													 cdReal* fraction, int* axis)
{
	bool inside = true;
	for (int i = 0; i < CD_DIM; ++i)
	{
		inside = inside && lower[i] <= origin[i] && origin[i] <= upper[i];
	}
	if (inside)
	{
		return CD_SLAB_INSIDE;
	}

	cdReal enter = -CD_REAL_MAX, leave = CD_REAL_MAX;
	int enterAxis = -1;
	for (int i = 0; i < CD_DIM; ++i)
	{
		if (translation[i] == CD_R(0.0))
		{
			if (origin[i] < lower[i] || upper[i] < origin[i])
			{
				return CD_SLAB_MISS; /* parallel to this slab and outside it */
			}
			continue;
		}
		cdReal tNear = (lower[i] - origin[i]) / translation[i];
		cdReal tFar = (upper[i] - origin[i]) / translation[i];
		if (tNear > tFar)
		{
			cdReal swap = tNear;
			tNear = tFar;
			tFar = swap;
		}
		if (tNear > enter)
		{
			enter = tNear;
			enterAxis = i;
		}
		leave = cdMin(leave, tFar);
	}

	/* The origin is outside some slab it is not parallel to, so enterAxis is set and enter >= 0
	 * up to round-off (clamped below). */
	if (enterAxis < 0 || enter > leave || enter > CD_R(1.0) || leave < CD_R(0.0))
	{
		return CD_SLAB_MISS;
	}
	*fraction = cdClamp(enter, CD_R(0.0), CD_R(1.0));
	*axis = enterAxis;
	return CD_SLAB_HIT;
}
#endif
