/* collide: the incident edge on a tie within round-off, shared by the 2D clipping of manifold2.c and
 * the chain segments' own clipping (chain_manifold2.c), which must take the same decisions. */
#ifndef COLLIDE_INCIDENT_TIE2_H
#define COLLIDE_INCIDENT_TIE2_H

#include "collide/math2.h"

/* How far the core edge (start, end) lies outside the reference extent [0, upper] along the
 * tangent from v1 (0 when it reaches over it). */
static inline cdReal cd2CoreGapAlong(cd2Vec tangent, cd2Vec v1, cdReal upper, cd2Vec start, cd2Vec end)
{
	cdReal a = cd2Dot(tangent, cd2Sub(start, v1)), b = cd2Dot(tangent, cd2Sub(end, v1));
	return cdMax(cdMax(cdMin(a, b) - upper, -cdMax(a, b)), CD_R(0.0));
}

/* Out of line and cold where the compiler allows: inlined, its rare work made the clipping's common
 * path slower (the 2D box-box manifold 4%). */
#if defined(__GNUC__) || defined(__clang__)
#define CD2_TIE_COLD __attribute__((noinline, cold))
#else
#define CD2_TIE_COLD
#endif

/* The incident edge when the first edge facing the reference normal n most (`edge`, whose dot with
 * n is `lowest`) lies wholly beyond a side line of the reference extent: a neighbour facing n as
 * much within round-off (edges of a sliver at 1e9 whose normals round to the same floats) whose
 * core edge lies nearer the extent, else `edge`. Measured on the core ends, as the clipping's kept
 * end is (a large radius moves the surface ends along the face). */
static CD2_TIE_COLD int cd2TiedIncidentEdge(const cd2Vec* vertices, const cd2Vec* normals, int count,
											cd2Vec n, cdReal lowest, int edge, cd2Vec tangent, cd2Vec v1,
											cdReal upper)
{
	int chosen = edge;
	cdReal gap =
		cd2CoreGapAlong(tangent, v1, upper, vertices[edge], vertices[edge + 1 < count ? edge + 1 : 0]);
	int neighbours[2] = {edge > 0 ? edge - 1 : count - 1, edge + 1 < count ? edge + 1 : 0};
	for (int k = 0; k < 2; ++k)
	{
		int candidate = neighbours[k];
		if (cd2Dot(n, normals[candidate]) - lowest > CD_R(4.0) * CD_REAL_EPSILON)
		{
			continue;
		}
		cdReal candidateGap = cd2CoreGapAlong(tangent, v1, upper, vertices[candidate],
											  vertices[candidate + 1 < count ? candidate + 1 : 0]);
		if (candidateGap < gap)
		{
			gap = candidateGap;
			chosen = candidate;
		}
	}
	return chosen;
}

#endif
