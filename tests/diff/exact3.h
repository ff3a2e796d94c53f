// Exact signed distance between spheres, capsules, boxes and hulls, in double, for the 3D
// differential tests (diff_ccd, diff_fcl). Written independently of src/query.
//
// Every shape is a core (a point, a segment or a convex polytope) inflated by a radius. Cores
// that are a point or a segment are compared in closed form (Ericson's closest points between
// segments). When a polytope takes part, the separating axis test over the complete axis set
// (face normals of the polytopes and cross products of the edge directions, the segment's
// included) decides whether the cores intersect; its value is then minus the exact penetration
// depth of the cores. Separated cores: the distance is the smallest over vertex-triangle and
// edge-edge pairs, which is exact for disjoint convex polytopes. The signed distance of the
// shapes is that of the cores minus the sum of the radii (a Minkowski sum with a ball adds its
// radius to the depth as to the distance; for flat cores that intersect the depth is the radius).
#ifndef COLLIDE_DIFF_EXACT3_H
#define COLLIDE_DIFF_EXACT3_H

#include "collide/collide.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace exact3
{
struct V3
{
	double x, y, z;
};
inline V3 operator+(V3 a, V3 b)
{
	return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline V3 operator-(V3 a, V3 b)
{
	return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline V3 operator*(double s, V3 a)
{
	return {s * a.x, s * a.y, s * a.z};
}
inline double Dot(V3 a, V3 b)
{
	return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline V3 Cross(V3 a, V3 b)
{
	return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double Length(V3 a)
{
	return std::sqrt(Dot(a, a));
}
inline V3 FromVec(cd3Vec v)
{
	return {(double)v.x, (double)v.y, (double)v.z};
}

// The rotation of a (normalized in double) quaternion applied to v.
inline V3 Rotate(cd3Quat q, V3 v)
{
	double x = (double)q.x, y = (double)q.y, z = (double)q.z, w = (double)q.w;
	double n = std::sqrt(x * x + y * y + z * z + w * w);
	x /= n;
	y /= n;
	z /= n;
	w /= n;
	V3 u = {x, y, z};
	V3 t = 2.0 * Cross(u, v);
	return v + w * t + Cross(u, t);
}

enum class Kind
{
	Point,
	Segment,
	Polytope
};

struct Core
{
	Kind kind = Kind::Point;
	double radius = 0.0;
	std::vector<V3> vertices;
	std::vector<std::pair<int, int>> edges; // vertex index pairs, each edge once
	std::vector<V3> normals;				// face normals (polytopes)
	std::vector<int> triangles;				// boundary triangles, 3 vertex indices each
	double size = 0.0;						// diagonal of the bounds plus twice the radius
};

inline void FinishSize(Core* c)
{
	V3 lo = c->vertices[0], hi = c->vertices[0];
	for (V3 v : c->vertices)
	{
		lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
		hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
	}
	c->size = Length(hi - lo) + 2.0 * c->radius;
}

inline Core FromHull(const cd3Hull* h, cd3Vec position, cd3Quat rotation)
{
	Core c;
	c.kind = Kind::Polytope;
	V3 p = FromVec(position);
	for (int i = 0; i < h->vertexCount; ++i)
	{
		c.vertices.push_back(p + Rotate(rotation, FromVec(h->vertices[i])));
	}
	for (int i = 0; i < h->edgeCount; ++i)
	{
		if (h->edges[i].twin > i)
		{
			c.edges.push_back({h->edges[i].origin, h->edges[h->edges[i].twin].origin});
		}
	}
	for (int f = 0; f < h->faceCount; ++f)
	{
		c.normals.push_back(Rotate(rotation, FromVec(h->planes[f].normal)));
		int first = h->faceEdges[f];
		int e = h->edges[first].next;
		while (h->edges[e].next != first)
		{
			c.triangles.push_back(h->edges[first].origin);
			c.triangles.push_back(h->edges[e].origin);
			c.triangles.push_back(h->edges[h->edges[e].next].origin);
			e = h->edges[e].next;
		}
	}
	FinishSize(&c);
	return c;
}

// Boxes become the hull of their corners (cd3MakeBoxHull is exact on +-halfExtents); the hull is
// only read here.
inline Core FromBox(cd3Box b)
{
	cd3Hull* h = nullptr;
	Core c;
	if (cd3MakeBoxHull(b.halfExtents, &h) == CD_OK)
	{
		c = FromHull(h, b.center, b.rotation);
		cd3DestroyHull(h);
	}
	return c;
}

inline Core FromShape(const cd3Shape& s)
{
	Core c;
	switch (s.type)
	{
		case CD3_SHAPE_SPHERE:
			c.vertices.push_back(FromVec(s.sphere.center));
			c.radius = (double)s.sphere.radius;
			break;
		case CD3_SHAPE_CAPSULE:
			c.radius = (double)s.capsule.radius;
			c.vertices.push_back(FromVec(s.capsule.p1));
			if (!cd3VecEqual(s.capsule.p1, s.capsule.p2))
			{
				c.kind = Kind::Segment;
				c.vertices.push_back(FromVec(s.capsule.p2));
				c.edges.push_back({0, 1});
			}
			break;
		case CD3_SHAPE_BOX:
			return FromBox(s.box);
		case CD3_SHAPE_HULL:
			return FromHull(s.hull.hull, s.hull.transform.p, s.hull.transform.q);
		default:
			break;
	}
	FinishSize(&c);
	return c;
}

// Closest points between segments p1q1 and p2q2 (Ericson 5.1.9), either may be a point.
inline double SegmentSegmentDistance(V3 p1, V3 q1, V3 p2, V3 q2)
{
	V3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
	double a = Dot(d1, d1), e = Dot(d2, d2), f = Dot(d2, r);
	double s = 0.0, t = 0.0;
	if (a == 0.0 && e == 0.0)
	{
		return Length(p1 - p2);
	}
	if (a == 0.0)
	{
		t = std::clamp(f / e, 0.0, 1.0);
	}
	else
	{
		double c = Dot(d1, r);
		if (e == 0.0)
		{
			s = std::clamp(-c / a, 0.0, 1.0);
		}
		else
		{
			double b = Dot(d1, d2), denom = a * e - b * b;
			s = denom > 0.0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
			t = (b * s + f) / e;
			if (t < 0.0)
			{
				t = 0.0;
				s = std::clamp(-c / a, 0.0, 1.0);
			}
			else if (t > 1.0)
			{
				t = 1.0;
				s = std::clamp((b - c) / a, 0.0, 1.0);
			}
		}
	}
	return Length((p1 + s * d1) - (p2 + t * d2));
}

// Distance from p to the triangle abc (Ericson 5.1.5).
inline double PointTriangleDistance(V3 p, V3 a, V3 b, V3 c)
{
	V3 ab = b - a, ac = c - a, ap = p - a;
	double d1 = Dot(ab, ap), d2 = Dot(ac, ap);
	if (d1 <= 0.0 && d2 <= 0.0)
	{
		return Length(p - a);
	}
	V3 bp = p - b;
	double d3 = Dot(ab, bp), d4 = Dot(ac, bp);
	if (d3 >= 0.0 && d4 <= d3)
	{
		return Length(p - b);
	}
	double vc = d1 * d4 - d3 * d2;
	if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
	{
		return Length(p - (a + (d1 / (d1 - d3)) * ab));
	}
	V3 cp = p - c;
	double d5 = Dot(ab, cp), d6 = Dot(ac, cp);
	if (d6 >= 0.0 && d5 <= d6)
	{
		return Length(p - c);
	}
	double vb = d5 * d2 - d1 * d6;
	if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
	{
		return Length(p - (a + (d2 / (d2 - d6)) * ac));
	}
	double va = d3 * d6 - d5 * d4;
	if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
	{
		return Length(p - (b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b)));
	}
	double denom = 1.0 / (va + vb + vc);
	return Length(p - (a + (vb * denom) * ab + (vc * denom) * ac));
}

// Largest separation of the two vertex sets along the axis (negative: overlap along it).
inline double AxisSeparation(const Core& a, const Core& b, V3 axis)
{
	double len = Length(axis);
	double loA = INFINITY, hiA = -INFINITY, loB = INFINITY, hiB = -INFINITY;
	for (V3 v : a.vertices)
	{
		double d = Dot(v, axis) / len;
		loA = std::min(loA, d);
		hiA = std::max(hiA, d);
	}
	for (V3 v : b.vertices)
	{
		double d = Dot(v, axis) / len;
		loB = std::min(loB, d);
		hiB = std::max(hiB, d);
	}
	return std::max(loB - hiA, loA - hiB);
}

struct Sat
{
	double faceA = -INFINITY, faceB = -INFINITY, edge = -INFINITY;
	double Best() const
	{
		return std::max(faceA, std::max(faceB, edge));
	}
	// How far the runner-up axis family is from the best one (a tie when small).
	double TieGap() const
	{
		double v[3] = {faceA, faceB, edge};
		std::sort(v, v + 3);
		return v[2] - v[1];
	}
};

inline Sat SeparatingAxes(const Core& a, const Core& b)
{
	Sat s;
	for (V3 n : a.normals)
	{
		s.faceA = std::max(s.faceA, AxisSeparation(a, b, n));
	}
	for (V3 n : b.normals)
	{
		s.faceB = std::max(s.faceB, AxisSeparation(a, b, n));
	}
	for (auto ea : a.edges)
	{
		V3 u = a.vertices[(size_t)ea.second] - a.vertices[(size_t)ea.first];
		for (auto eb : b.edges)
		{
			V3 w = b.vertices[(size_t)eb.second] - b.vertices[(size_t)eb.first];
			V3 c = Cross(u, w);
			if (Length(c) > 1e-9 * Length(u) * Length(w))
			{
				s.edge = std::max(s.edge, AxisSeparation(a, b, c));
			}
		}
	}
	return s;
}

// Distance between the cores, valid when they are disjoint.
inline double FeatureDistance(const Core& a, const Core& b)
{
	double best = INFINITY;
	auto pointToCore = [&](V3 p, const Core& c) {
		for (V3 v : c.vertices)
		{
			best = std::min(best, Length(p - v));
		}
		for (auto e : c.edges)
		{
			best = std::min(best, SegmentSegmentDistance(p, p, c.vertices[(size_t)e.first],
														 c.vertices[(size_t)e.second]));
		}
		for (size_t i = 0; i + 2 < c.triangles.size(); i += 3)
		{
			best = std::min(best, PointTriangleDistance(p, c.vertices[(size_t)c.triangles[i]],
														c.vertices[(size_t)c.triangles[i + 1]],
														c.vertices[(size_t)c.triangles[i + 2]]));
		}
	};
	for (V3 p : a.vertices)
	{
		pointToCore(p, b);
	}
	for (V3 p : b.vertices)
	{
		pointToCore(p, a);
	}
	for (auto ea : a.edges)
	{
		for (auto eb : b.edges)
		{
			best = std::min(
				best, SegmentSegmentDistance(a.vertices[(size_t)ea.first], a.vertices[(size_t)ea.second],
											 b.vertices[(size_t)eb.first], b.vertices[(size_t)eb.second]));
		}
	}
	return best;
}

struct Signed
{
	double distance; // negative: minus the penetration depth
	double tieGap;	 // overlapping SAT pairs: gap between the best two axis families (else INFINITY)
	double size;	 // sum of the two shapes' sizes
};

inline Signed SignedDistance(const Core& a, const Core& b)
{
	Signed r;
	r.size = a.size + b.size;
	r.tieGap = INFINITY;
	double radius = a.radius + b.radius;
	if (a.kind != Kind::Polytope && b.kind != Kind::Polytope)
	{
		V3 a2 = a.vertices.back(), b2 = b.vertices.back();
		r.distance = SegmentSegmentDistance(a.vertices[0], a2, b.vertices[0], b2) - radius;
		return r;
	}
	Sat sat = SeparatingAxes(a, b);
	double best = sat.Best();
	if (best <= 0.0)
	{
		r.distance = best - radius;
		r.tieGap = sat.TieGap();
		return r;
	}
	r.distance = FeatureDistance(a, b) - radius;
	return r;
}

inline Signed SignedDistance(const cd3Shape& a, const cd3Shape& b)
{
	return SignedDistance(FromShape(a), FromShape(b));
}
} // namespace exact3

#endif
