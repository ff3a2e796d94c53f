/* collide tool: every pairwise query of a scene. Library shapes go through the generic
 * dispatchers (cdNOverlap for the yes/no answer, cdNDistance for the closest points, and in 2D
 * cd2Collide for the contact manifold); points are not library shapes, so the tool asks
 * cdNPointInShape and cdNClosestPointOnShape for them. */
#include "scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static void store2(double out[3], cd2Vec v)
{
	out[0] = (double)v.x;
	out[1] = (double)v.y;
	out[2] = 0.0;
}

static void store3(double out[3], cd3Vec v)
{
	out[0] = (double)v.x;
	out[1] = (double)v.y;
	out[2] = (double)v.z;
}

static double distanceBetween(const double a[3], const double b[3])
{
	double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
	return sqrt(dx * dx + dy * dy + dz * dz);
}

/* The contact manifold of two library shapes (every 2D shape type has one). */
static void collidePair2(const ToolShape* a, const ToolShape* b, ToolPairResult* pair)
{
	cd2Manifold manifold = cd2Collide(&a->shape2, &b->shape2, (cdReal)TOOL_CONTACT_SPECULATIVE_DISTANCE);
	int count = cdMinInt(cdMaxInt(manifold.pointCount, 0), 2);
	pair->hasContact = count > 0;
	pair->contactCount = count;
	if (count == 0)
	{
		return;
	}
	pair->contactNormal[0] = (double)manifold.normal.x;
	pair->contactNormal[1] = (double)manifold.normal.y;
	pair->deepestSeparation = (double)manifold.points[0].separation;
	for (int i = 0; i < count; ++i)
	{
		pair->contactPoints[i][0] = (double)manifold.points[i].point.x;
		pair->contactPoints[i][1] = (double)manifold.points[i].point.y;
		pair->deepestSeparation = fmin(pair->deepestSeparation, (double)manifold.points[i].separation);
	}
}

static void queryPair2(const ToolShape* a, const ToolShape* b, ToolPairResult* pair)
{
	if (a->isPoint && b->isPoint)
	{
		pair->overlap = cd2VecEqual(a->point2, b->point2);
		store2(pair->pointA, a->point2);
		store2(pair->pointB, b->point2);
	}
	else if (a->isPoint || b->isPoint)
	{
		const ToolShape* point = a->isPoint ? a : b;
		const ToolShape* shape = a->isPoint ? b : a;
		cd2Vec closest = cd2ClosestPointOnShape(&shape->shape2, point->point2);
		pair->overlap = cd2PointInShape(&shape->shape2, point->point2);
		store2(a->isPoint ? pair->pointA : pair->pointB, point->point2);
		store2(a->isPoint ? pair->pointB : pair->pointA, closest);
	}
	else
	{
		pair->overlap = cd2Overlap(&a->shape2, &b->shape2);
		cd2ClosestPoints closest = cd2Distance(&a->shape2, &b->shape2);
		store2(pair->pointA, closest.pointA);
		store2(pair->pointB, closest.pointB);
		pair->distance = (double)closest.distance;
		collidePair2(a, b, pair);
		return;
	}
	pair->distance = distanceBetween(pair->pointA, pair->pointB);
}

static void queryPair3(const ToolShape* a, const ToolShape* b, ToolPairResult* pair)
{
	if (a->isPoint && b->isPoint)
	{
		pair->overlap = cd3VecEqual(a->point3, b->point3);
		store3(pair->pointA, a->point3);
		store3(pair->pointB, b->point3);
	}
	else if (a->isPoint || b->isPoint)
	{
		const ToolShape* point = a->isPoint ? a : b;
		const ToolShape* shape = a->isPoint ? b : a;
		cd3Vec closest = cd3ClosestPointOnShape(&shape->shape3, point->point3);
		pair->overlap = cd3PointInShape(&shape->shape3, point->point3);
		store3(a->isPoint ? pair->pointA : pair->pointB, point->point3);
		store3(a->isPoint ? pair->pointB : pair->pointA, closest);
	}
	else
	{
		pair->overlap = cd3Overlap(&a->shape3, &b->shape3);
		cd3ClosestPoints closest = cd3Distance(&a->shape3, &b->shape3);
		store3(pair->pointA, closest.pointA);
		store3(pair->pointB, closest.pointB);
		pair->distance = (double)closest.distance;
		return;
	}
	pair->distance = distanceBetween(pair->pointA, pair->pointB);
}

void toolQueryPair(const ToolScene* scene, int i, int j, ToolPairResult* pair)
{
	memset(pair, 0, sizeof *pair);
	pair->a = i;
	pair->b = j;
	if (scene->dimension == 2)
	{
		queryPair2(&scene->shapes[i], &scene->shapes[j], pair);
	}
	else
	{
		queryPair3(&scene->shapes[i], &scene->shapes[j], pair);
	}
}

bool toolQueryScene(const ToolScene* scene, ToolSceneResult* result)
{
	result->scene = scene;
	result->pairs = NULL;
	result->pairCount = 0;
	result->overlapCount = 0;
	int n = scene->shapeCount;
	int pairCount = n * (n - 1) / 2;
	if (pairCount == 0)
	{
		return true;
	}
	result->pairs = calloc((size_t)pairCount, sizeof(ToolPairResult));
	if (result->pairs == NULL)
	{
		return false;
	}
	for (int i = 0; i < n; ++i)
	{
		for (int j = i + 1; j < n; ++j)
		{
			ToolPairResult* pair = &result->pairs[result->pairCount++];
			toolQueryPair(scene, i, j, pair);
			result->overlapCount += pair->overlap ? 1 : 0;
		}
	}
	return true;
}

void toolFreeSceneResult(ToolSceneResult* result)
{
	free(result->pairs);
	result->pairs = NULL;
	result->pairCount = 0;
}
