/* Mass properties of the solid 2D shapes: closed forms for the circle, capsule and box; the
 * polygon as a fan of triangles, its rounding as a strip of rectangles along the edges plus
 * circular sectors at the corners. Everything is accumulated in double. */
#include "collide/geometry2.h"

#include "query/pairs2.h"

#define MASS_PI 3.14159265358979323846

/* Mass, first moment and polar second moment about a reference point, summed over pieces. */
typedef struct Moments
{
	double mass, mx, my, polar;
} Moments;

/* Triangle (0, a, b) relative to the reference point, signed by its winding. */
static void AddTriangle(Moments* m, double ax, double ay, double bx, double by, double density)
{
	double area = 0.5 * (ax * by - ay * bx);
	double mass = density * area;
	m->mass += mass;
	m->mx += mass * (ax + bx) / 3.0;
	m->my += mass * (ay + by) / 3.0;
	m->polar += mass * (ax * ax + ax * bx + bx * bx + ay * ay + ay * by + by * by) / 6.0;
}

static cd2MassData Finish(const Moments* m, double refX, double refY)
{
	cd2MassData data;
	double cx = m->mass > 0.0 ? m->mx / m->mass : 0.0, cy = m->mass > 0.0 ? m->my / m->mass : 0.0;
	data.mass = (cdReal)m->mass;
	data.center = cd2MakeVec((cdReal)(refX + cx), (cdReal)(refY + cy));
	/* Parallel axis: from the reference point to the centre of mass. */
	data.rotationalInertia = (cdReal)(m->polar - m->mass * (cx * cx + cy * cy));
	return data;
}

cd2MassData cd2ComputeCircleMass(cd2Circle circle, cdReal density)
{
	double r = (double)circle.radius;
	double mass = (double)density * MASS_PI * r * r;
	cd2MassData data;
	data.mass = (cdReal)mass;
	data.center = circle.center;
	data.rotationalInertia = (cdReal)(0.5 * mass * r * r);
	return data;
}

cd2MassData cd2ComputeCapsuleMass(cd2Capsule capsule, cdReal density)
{
	double r = (double)capsule.radius, rho = (double)density;
	double dx = (double)capsule.p2.x - (double)capsule.p1.x, dy = (double)capsule.p2.y - (double)capsule.p1.y;
	double length = sqrt(dx * dx + dy * dy);
	double box = rho * 2.0 * r * length;
	double disk = rho * MASS_PI * r * r;
	/* Each half disk: r^2 / 2 about its flat side's centre, less (4r / 3 pi)^2 to its centroid,
	 * moved out to L / 2 + 4r / 3 pi. */
	double inertia = box * (length * length + 4.0 * r * r) / 12.0 +
					 disk * (0.5 * r * r + 0.25 * length * length + 4.0 * r * length / (3.0 * MASS_PI));
	cd2MassData data;
	data.mass = (cdReal)(box + disk);
	data.center = cd2Lerp(capsule.p1, capsule.p2, CD_R(0.5));
	data.rotationalInertia = (cdReal)inertia;
	return data;
}

static cd2MassData RectangleMass(cd2Vec center, cd2Vec halfExtents, cdReal density)
{
	double x = (double)halfExtents.x, y = (double)halfExtents.y;
	double mass = (double)density * 4.0 * x * y;
	cd2MassData data;
	data.mass = (cdReal)mass;
	data.center = center;
	data.rotationalInertia = (cdReal)(mass * (x * x + y * y) / 3.0);
	return data;
}

cd2MassData cd2ComputeAabbMass(cd2Aabb aabb, cdReal density)
{
	return RectangleMass(cd2Lerp(aabb.min, aabb.max, CD_R(0.5)),
						 cd2Scale(CD_R(0.5), cd2Sub(aabb.max, aabb.min)), density);
}

cd2MassData cd2ComputeBoxMass(cd2Box box, cdReal density)
{
	return RectangleMass(box.center, box.halfExtents, density);
}

cd2MassData cd2ComputePolygonMass(const cd2Polygon* polygon, cdReal density)
{
	CD_ASSERT(polygon != NULL && polygon->count >= 1);
	int n = polygon->count;
	double refX = 0.0, refY = 0.0;
	for (int i = 0; i < n; ++i)
	{
		refX += (double)polygon->vertices[i].x;
		refY += (double)polygon->vertices[i].y;
	}
	refX /= (double)n;
	refY /= (double)n;
	double rho = (double)density, r = (double)polygon->radius;
	Moments m = {0.0, 0.0, 0.0, 0.0};
	for (int i = 0; i < n; ++i)
	{
		int j = (i + 1) % n;
		double ax = (double)polygon->vertices[i].x - refX, ay = (double)polygon->vertices[i].y - refY;
		double bx = (double)polygon->vertices[j].x - refX, by = (double)polygon->vertices[j].y - refY;
		AddTriangle(&m, ax, ay, bx, by, rho);
		if (r <= 0.0 || n < 2)
		{
			continue;
		}
		/* The rounding: the rectangle on edge i-j pushed out by r along its outward normal (its
		 * counter-clockwise outline as a fan from the reference point) ... */
		double ex = bx - ax, ey = by - ay, el = sqrt(ex * ex + ey * ey);
		if (el > 0.0)
		{
			double nx = ey / el * r, ny = -ex / el * r;
			double quad[5][2] = {{ax, ay}, {ax + nx, ay + ny}, {bx + nx, by + ny}, {bx, by}, {ax, ay}};
			for (int k = 0; k < 4; ++k)
			{
				AddTriangle(&m, quad[k][0], quad[k][1], quad[k + 1][0], quad[k + 1][1], rho);
			}
		}
	}
	if (r > 0.0)
	{
		/* ... and a circular sector at each corner, between its two edges' normals. */
		for (int i = 0; i < n; ++i)
		{
			int h = (i + n - 1) % n, j = (i + 1) % n;
			double px = (double)polygon->vertices[i].x, py = (double)polygon->vertices[i].y;
			double inX = px - (double)polygon->vertices[h].x, inY = py - (double)polygon->vertices[h].y;
			double outX = (double)polygon->vertices[j].x - px, outY = (double)polygon->vertices[j].y - py;
			double angle = n < 2 ? 2.0 * MASS_PI : atan2(inX * outY - inY * outX, inX * outX + inY * outY);
			if (n == 2)
			{
				angle = MASS_PI; /* a rounded segment: each end is a half disk */
			}
			if (angle <= 0.0)
			{
				continue;
			}
			double mass = rho * 0.5 * angle * r * r;
			/* Centroid along the bisector of the two normals, 4 r sin(angle / 2) / (3 angle). */
			double d = angle > 0.0 ? 4.0 * r * sin(0.5 * angle) / (3.0 * angle) : 0.0;
			double inLength = sqrt(inX * inX + inY * inY), outLength = sqrt(outX * outX + outY * outY);
			double bx = 0.0, by = 0.0;
			if (inLength > 0.0 && outLength > 0.0)
			{
				bx = inY / inLength + outY / outLength;
				by = -inX / inLength - outX / outLength;
			}
			double bl = sqrt(bx * bx + by * by);
			if (bl > 0.0)
			{
				bx /= bl;
				by /= bl;
			}
			double cx = px - refX + d * bx, cy = py - refY + d * by;
			m.mass += mass;
			m.mx += mass * cx;
			m.my += mass * cy;
			/* mr^2/2 about the corner, less m d^2 to the centroid, plus m |c|^2 to the reference. */
			m.polar += 0.5 * mass * r * r - mass * d * d + mass * (cx * cx + cy * cy);
		}
	}
	return Finish(&m, refX, refY);
}

/* A segment has no area: zero mass at its midpoint (the shape table's ComputeMass for Segment). */
static cd2MassData SegmentMass(cd2Segment segment, cdReal density)
{
	(void)density;
	cd2MassData none;
	none.mass = CD_R(0.0);
	none.center = cd2Lerp(segment.p1, segment.p2, CD_R(0.5));
	none.rotationalInertia = CD_R(0.0);
	return none;
}

cd2MassData cd2ComputeShapeMass(const cd2Shape* shape, cdReal density)
{
	CD_ASSERT(shape != NULL);
	switch (shape->type)
	{
#define CD2_MASS_CASE(Name, PointIn, ClosestPointOn, Raycast, TypeName, Validate, ComputeAabb, ComputeMass,  \
					  ...)                                                                                   \
	case CD2_TYPE_##Name:                                                                                    \
		return ComputeMass(CD2_SHAPE_ARG(Name, shape), density);
		CD2_SHAPE_TABLE(CD2_MASS_CASE)
#undef CD2_MASS_CASE
		case CD2_SHAPE_TYPE_COUNT:
			break;
	}
	cd2MassData none;
	none.mass = CD_R(0.0);
	none.center = cd2MakeVec(CD_R(0.0), CD_R(0.0));
	none.rotationalInertia = CD_R(0.0);
	return none;
}
