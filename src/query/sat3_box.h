/* collide (internal): box pieces of the separating axis test that the box-box manifold needs
 * without building polytopes. Not installed. */
#ifndef COLLIDE_SAT3_BOX_H
#define COLLIDE_SAT3_BOX_H

#include "sat3.h"

/* Edge pairs whose cross product is shorter than this fraction of |eA| |eB| are parallel (as in
 * sat3.c). */
#define CD3_BOX_PARALLEL_SINE CD_R(1.0e-5)

/* The endpoints (origin, then the twin's origin) of half-edge `edge` of a box with these half
 * extents, in the box's frame, numbered as by cd3InitBoxPolytope. */
void cd3BoxEdgeLocal(cd3Vec halfExtents, int edge, cd3Vec* p1, cd3Vec* p2);

/* The box edge parallel to axis `axis` that supports the box along `direction` (box frame). */
static inline int cd3SupportingBoxEdge(int axis, cd3Vec direction)
{
	/* CD3_BOX_EDGE_FROM[v][axis]: the half-edge from vertex v (its `axis` bit clear) to v with that bit
	 * set; -1 where the bit is already set. */
	static const int CD3_BOX_EDGE_FROM[8][3] = {{9, 17, 1},	 {-1, 5, 10},  {18, -1, 13}, {-1, -1, 6},
												{21, 2, -1}, {-1, 22, -1}, {14, -1, -1}, {-1, -1, -1}};

	int vertex = 0;
	for (int k = 0; k < 3; ++k)
	{
		if (k != axis && cd3GetComponent(direction, k) > CD_R(0.0))
		{
			vertex |= 1 << k;
		}
	}
	return CD3_BOX_EDGE_FROM[vertex][axis];
}

/* |a| as a max, which compiles to one instruction: the signs of the box SAT's matrix entries and
 * centre offsets are random, so cdAbs's comparison branch mispredicts half the time. */
static inline cdReal cd3AbsNoBranch(cdReal a)
{
	return cdMax(a, -a);
}

/* cd3SatBoxes writing into *result, inline: the box-box manifold reads the result at once, and
 * a result returned through memory stalls on store forwarding. */
static inline void cd3SatBoxesInPlace(const cd3Box* boxA, const cd3Box* boxB, cd3SatResult* result,
									  cd3Mat33* rotation, cd3Vec* translation)
{
	cd3SatResult r;
	cd3Box a = *boxA, b = *boxB;
	cd3Quat q = cd3InvMulQuat(a.rotation, b.rotation); /* B's axes in A's frame */
	cd3Vec t = cd3InvRotateVector(a.rotation, cd3Sub(b.center, a.center));
	cd3Mat33 matrix = cd3MakeMatFromQuat(q);
	*rotation = matrix;
	*translation = t;
	cd3Vec axisB[3] = {matrix.cx, matrix.cy, matrix.cz};
	cdReal ha[3] = {a.halfExtents.x, a.halfExtents.y, a.halfExtents.z};
	cdReal hb[3] = {b.halfExtents.x, b.halfExtents.y, b.halfExtents.z};
	/* rot[i][j] = A's axis i . B's axis j */
	cdReal rot[3][3], absRot[3][3];
	for (int j = 0; j < 3; ++j)
	{
		rot[0][j] = axisB[j].x;
		rot[1][j] = axisB[j].y;
		rot[2][j] = axisB[j].z;
	}
	for (int i = 0; i < 3; ++i)
	{
		for (int j = 0; j < 3; ++j)
		{
			absRot[i][j] = cd3AbsNoBranch(rot[i][j]);
		}
	}
	cdReal tA[3] = {t.x, t.y, t.z};

	r.faceSeparationA = -CD_REAL_MAX;
	r.faceA = 0;
	for (int i = 0; i < 3; ++i)
	{
		cdReal radiusB = hb[0] * absRot[i][0] + hb[1] * absRot[i][1] + hb[2] * absRot[i][2];
		cdReal separation = cd3AbsNoBranch(tA[i]) - ha[i] - radiusB;
		if (separation > r.faceSeparationA)
		{
			r.faceSeparationA = separation;
			r.faceA = 2 * i + (tA[i] > CD_R(0.0) ? 1 : 0);
		}
	}
	r.faceSeparationB = -CD_REAL_MAX;
	r.faceB = 0;
	for (int j = 0; j < 3; ++j)
	{
		cdReal tB = cd3Dot(t, axisB[j]);
		cdReal radiusA = ha[0] * absRot[0][j] + ha[1] * absRot[1][j] + ha[2] * absRot[2][j];
		cdReal separation = cd3AbsNoBranch(tB) - hb[j] - radiusA;
		if (separation > r.faceSeparationB)
		{
			r.faceSeparationB = separation;
			/* B's face toward A: A lies on B's negative side when tB > 0. */
			r.faceB = 2 * j + (tB > CD_R(0.0) ? 0 : 1);
		}
	}
	r.edgeSeparation = -CD_REAL_MAX;
	r.edgeA = -1;
	r.edgeB = -1;
	cd3Vec bestAxis = cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(0.0));
	int bestI = 0, bestJ = 0;
	cdReal faceBest = cdMax(r.faceSeparationA, r.faceSeparationB);
	/* Edge axes A_i x B_j in A's frame: (0, -rot[2][j], rot[1][j]) for i = 0 and its cyclic
	 * shifts, so the projections are sums of the matrix entries. */
	for (int i = 0; i < 3; ++i)
	{
		int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
		for (int j = 0; j < 3; ++j)
		{
			int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
			cdReal length2 = rot[i1][j] * rot[i1][j] + rot[i2][j] * rot[i2][j];
			if (!(length2 > CD3_BOX_PARALLEL_SINE * CD3_BOX_PARALLEL_SINE))
			{
				continue;
			}
			cdReal radiusA = ha[i1] * absRot[i2][j] + ha[i2] * absRot[i1][j];
			cdReal radiusB = hb[j1] * absRot[i][j2] + hb[j2] * absRot[i][j1];
			cdReal centre = tA[i2] * rot[i1][j] - tA[i1] * rot[i2][j];
			cdReal gap = cd3AbsNoBranch(centre) - radiusA - radiusB; /* separation * sqrt(length2) */
			/* An edge axis matters only when it beats every axis so far: decided on squares, so
			 * that only the winners pay a square root. */
			cdReal threshold = cdMax(r.edgeSeparation, faceBest);
			cdReal bar = threshold * threshold * length2;
			bool ahead = threshold >= CD_R(0.0), behind = !ahead;
			bool beats = (ahead & (gap > CD_R(0.0)) & (gap * gap > bar)) |
						 (behind & ((gap >= CD_R(0.0)) | (gap * gap < bar)));
			if (!beats)
			{
				continue;
			}
			cdReal separation = gap / cdSqrt(length2);
			if (separation > r.edgeSeparation)
			{
				r.edgeSeparation = separation;
				cdReal components[3] = {CD_R(0.0), CD_R(0.0), CD_R(0.0)};
				components[i1] = -rot[i2][j];
				components[i2] = rot[i1][j];
				cd3Vec axis = cd3Normalize(cd3MakeVec(components[0], components[1], components[2]));
				bestAxis = centre < CD_R(0.0) ? cd3Neg(axis) : axis;
				bestI = i;
				bestJ = j;
			}
		}
	}
	if (r.edgeSeparation > -CD_REAL_MAX)
	{
		r.edgeA = cd3SupportingBoxEdge(bestI, bestAxis);
		cd3Vec inB = {-cd3Dot(bestAxis, axisB[0]), -cd3Dot(bestAxis, axisB[1]), -cd3Dot(bestAxis, axisB[2])};
		r.edgeB = cd3SupportingBoxEdge(bestJ, inB);
	}
	r.edgeNormal = cd3RotateVector(a.rotation, bestAxis);
	*result = r;
}

#endif
