/* libFuzzer target for cd3ComputeHull: arbitrary point clouds (raw float bit patterns, small
 * lattices that make exact coplanar and collinear sets, near-duplicates, scales from tiny to
 * huge, far offsets). Never a crash; on success the hull validates, every vertex is an input
 * point and every input point lies inside within the hull's tolerance; a few queries on the hull
 * shape stay finite. On failure the result is one of the documented codes. */
#include "collide/collide.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if CD_DOUBLE
#define HULL_FUZZ_MAX 1e30
#else
#define HULL_FUZZ_MAX 1e9
#endif

static void Fail(const char* what, int count)
{
	fprintf(stderr, "fuzz_hull3: %s (%d points)\n", what, count);
	abort();
}

typedef struct Reader
{
	const uint8_t* data;
	size_t size, at;
} Reader;

static uint8_t Byte(Reader* r)
{
	return r->at < r->size ? r->data[r->at++] : 0;
}

static float RawFloat(Reader* r)
{
	uint32_t bits = 0;
	for (int i = 0; i < 4; ++i)
	{
		bits |= (uint32_t)Byte(r) << (8 * i);
	}
	float f;
	memcpy(&f, &bits, sizeof f);
	return f;
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	Reader r = {data, size, 0};
	uint8_t mode = Byte(&r);
	double scale = pow(10.0, (double)((int)Byte(&r) % 19 - 9));
	double offset = (Byte(&r) & 1) ? scale * pow(10.0, (double)(Byte(&r) % 6)) : 0.0;
	int count = (int)(size / 3);
	count = count > 4096 ? 4096 : count;
	cd3Vec* points = (cd3Vec*)malloc((size_t)(count > 0 ? count : 1) * sizeof(cd3Vec));
	for (int i = 0; i < count; ++i)
	{
		cdReal c[3];
		for (int k = 0; k < 3; ++k)
		{
			if (mode & 1)
			{
				/* Raw bit patterns: NaN, infinities, denormals, anything; clamped to the range
				 * in every other mode so that most inputs get built. */
				double v = (double)RawFloat(&r);
				if ((mode & 2) && isfinite(v))
				{
					v = v > HULL_FUZZ_MAX ? HULL_FUZZ_MAX : (v < -HULL_FUZZ_MAX ? -HULL_FUZZ_MAX : v);
				}
				c[k] = (cdReal)v;
			}
			else
			{
				/* A lattice of 16 values per axis (coplanar faces, collinear edges, duplicates),
				 * nudged by a few epsilons now and then (near-duplicates, near-coplanar). */
				uint8_t b = Byte(&r);
				double v = ((double)(b & 15) - 7.5) * scale + offset;
				if (b & 16)
				{
					v *= 1.0 + (double)((b >> 5) + 1) * (double)CD_REAL_EPSILON;
				}
				c[k] = (cdReal)v;
			}
		}
		points[i] = cd3MakeVec(c[0], c[1], c[2]);
	}

	cd3Hull* hull = NULL;
	cdResult result = cd3ComputeHull(points, count, &hull);
	if (result != CD_OK)
	{
		if (hull != NULL)
		{
			Fail("a failed build returned a hull", count);
		}
		if (result != CD_ERROR_DEGENERATE && result != CD_ERROR_NOT_FINITE &&
			result != CD_ERROR_OUT_OF_RANGE && result != CD_ERROR_TOO_MANY_POINTS &&
			result != CD_ERROR_OUT_OF_MEMORY)
		{
			Fail("unexpected result code", count);
		}
		free(points);
		return 0;
	}
	cdResult validation = cd3ValidateHull(hull);
	if (validation != CD_OK)
	{
		fprintf(stderr, "fuzz_hull3: cd3ValidateHull: %s\n", cdGetResultString(validation));
		Fail("the hull does not validate", count);
	}
	cdReal tolerance = cd3Hull_GetTolerance(hull);
	for (int i = 0; i < count; ++i)
	{
		for (int f = 0; f < hull->faceCount; ++f)
		{
			cd3Plane p = hull->planes[f];
			double h = (double)p.normal.x * (double)points[i].x + (double)p.normal.y * (double)points[i].y +
					   (double)p.normal.z * (double)points[i].z - (double)p.offset;
			if (h > (double)tolerance)
			{
				Fail("an input point lies outside the hull", count);
			}
		}
	}
	for (int v = 0; v < hull->vertexCount; ++v)
	{
		bool found = false;
		for (int i = 0; i < count && !found; ++i)
		{
			found = cd3VecEqual(hull->vertices[v], points[i]);
		}
		if (!found)
		{
			Fail("a hull vertex is not an input point", count);
		}
	}

	/* A few queries on the hull as a shape: finite answers. */
	cd3Shape shape = cd3MakeHullShape(hull, CD3_TRANSFORM_IDENTITY);
	cd3Vec center = cd3AabbCenter(hull->bounds);
	cd3Vec reach = cd3Sub(hull->bounds.max, hull->bounds.min);
	cd3Shape ball = cd3MakeSphereShape((cd3Sphere){cd3Add(center, reach), CD_R(0.25) * cd3Length(reach)});
	cd3ClosestPoints d = cd3Distance(&shape, &ball);
	if (!cdIsValidReal(d.distance) || !cd3IsValidVec(d.pointA) || !cd3IsValidVec(d.pointB) ||
		d.distance < CD_R(0.0))
	{
		Fail("distance not finite", count);
	}
	cd3RayHit hit;
	cd3Ray ray = {cd3Add(center, cd3Scale(CD_R(2.0), reach)), cd3Scale(CD_R(-4.0), reach)};
	if (cd3Raycast(&shape, ray, &hit) &&
		(!cd3IsValidVec(hit.point) || !cd3IsValidVec(hit.normal) || !(hit.fraction >= CD_R(0.0))))
	{
		Fail("ray hit not finite", count);
	}
	if (!cd3PointInShape(&shape, hull->centroid))
	{
		Fail("the centroid is not inside", count);
	}
	cd3MassData mass = cd3ComputeShapeMass(&shape, CD_R(1.0));
	if (!cdIsValidReal(mass.mass) || !cd3IsValidVec(mass.center))
	{
		Fail("mass not finite", count);
	}
	cd3DestroyHull(hull);
	free(points);
	return 0;
}
