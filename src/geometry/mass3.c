/* Mass properties of the solid 3D shapes: closed forms for the sphere, capsule and box, exact
 * polyhedral integration for hulls (sums over tetrahedra, as in Mirtich's and Eberly's
 * derivations, our own arrangement). Everything is accumulated in double. */
#include "collide/geometry3.h"

#include "query/pairs3.h"

/* A symmetric tensor in double, rows. */
typedef struct DMat
{
	double m[3][3];
} DMat;

static cd3Mat33 ToMat(const DMat* d)
{
	cd3Mat33 r;
	r.cx = cd3MakeVec((cdReal)d->m[0][0], (cdReal)d->m[1][0], (cdReal)d->m[2][0]);
	r.cy = cd3MakeVec((cdReal)d->m[0][1], (cdReal)d->m[1][1], (cdReal)d->m[2][1]);
	r.cz = cd3MakeVec((cdReal)d->m[0][2], (cdReal)d->m[1][2], (cdReal)d->m[2][2]);
	return r;
}

/* R diag(d) R^T, with R from the quaternion (in double). */
static DMat RotateDiagonal(cd3Quat q, const double d[3])
{
	cd3Quat u = cd3NormalizeQuat(q);
	double x = (double)u.x, y = (double)u.y, z = (double)u.z, w = (double)u.w;
	double r[3][3] = {{1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y)},
					  {2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x)},
					  {2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y)}};
	DMat out;
	for (int i = 0; i < 3; ++i)
	{
		for (int j = 0; j < 3; ++j)
		{
			out.m[i][j] = r[i][0] * d[0] * r[j][0] + r[i][1] * d[1] * r[j][1] + r[i][2] * d[2] * r[j][2];
		}
	}
	return out;
}

static cd3MassData Zero(cd3Vec center)
{
	cd3MassData data;
	data.mass = CD_R(0.0);
	data.center = center;
	data.inertia.cx = data.inertia.cy = data.inertia.cz = CD3_VEC_ZERO;
	return data;
}

cd3MassData cd3ComputeSphereMass(cd3Sphere sphere, cdReal density)
{
	double r = (double)sphere.radius;
	double mass = (double)density * 4.0 / 3.0 * 3.14159265358979323846 * r * r * r;
	double moment = 0.4 * mass * r * r;
	cd3MassData data = Zero(sphere.center);
	data.mass = (cdReal)mass;
	data.inertia.cx.x = data.inertia.cy.y = data.inertia.cz.z = (cdReal)moment;
	return data;
}

cd3MassData cd3ComputeCapsuleMass(cd3Capsule capsule, cdReal density)
{
	const double pi = 3.14159265358979323846;
	double r = (double)capsule.radius, rho = (double)density;
	double ax = (double)capsule.p2.x - (double)capsule.p1.x, ay = (double)capsule.p2.y - (double)capsule.p1.y;
	double az = (double)capsule.p2.z - (double)capsule.p1.z;
	double length = sqrt(ax * ax + ay * ay + az * az);
	double cylinder = rho * pi * r * r * length;
	double ball = rho * 4.0 / 3.0 * pi * r * r * r;
	/* Cylinder about its centre; each hemisphere's own moment (2/5 m r^2 about its flat face's
	 * centre, less m (3r/8)^2 to its centroid) moved out to L/2 + 3r/8. */
	double axial = cylinder * r * r / 2.0 + ball * 0.4 * r * r;
	double across = cylinder * (3.0 * r * r + length * length) / 12.0 +
					ball * (0.4 * r * r + length * length / 4.0 + 3.0 * length * r / 8.0);
	double u[3] = {0.0, 0.0, 0.0};
	if (length > 0.0)
	{
		u[0] = ax / length;
		u[1] = ay / length;
		u[2] = az / length;
	}
	DMat inertia;
	for (int i = 0; i < 3; ++i)
	{
		for (int j = 0; j < 3; ++j)
		{
			inertia.m[i][j] = (i == j ? across : 0.0) + (axial - across) * u[i] * u[j];
		}
	}
	cd3MassData data = Zero(cd3Lerp(capsule.p1, capsule.p2, CD_R(0.5)));
	data.mass = (cdReal)(cylinder + ball);
	data.inertia = ToMat(&inertia);
	return data;
}

static cd3MassData BoxMass(cd3Vec center, cd3Vec halfExtents, cd3Quat rotation, cdReal density)
{
	double x = (double)halfExtents.x, y = (double)halfExtents.y, z = (double)halfExtents.z;
	double mass = (double)density * 8.0 * x * y * z;
	double d[3] = {mass * (y * y + z * z) / 3.0, mass * (x * x + z * z) / 3.0, mass * (x * x + y * y) / 3.0};
	DMat inertia = RotateDiagonal(rotation, d);
	cd3MassData data = Zero(center);
	data.mass = (cdReal)mass;
	data.inertia = ToMat(&inertia);
	return data;
}

cd3MassData cd3ComputeAabbMass(cd3Aabb aabb, cdReal density)
{
	return BoxMass(cd3AabbCenter(aabb), cd3AabbHalfExtents(aabb), CD3_QUAT_IDENTITY, density);
}

cd3MassData cd3ComputeBoxMass(cd3Box box, cdReal density)
{
	return BoxMass(box.center, box.halfExtents, box.rotation, density);
}

cd3MassData cd3ComputeHullMass(cd3HullShape shape, cdReal density)
{
	CD_ASSERT(shape.hull != NULL);
	const cd3Hull* hull = shape.hull;
	/* Relative to the vertex mean, so that far-away hulls integrate without cancellation. */
	double ref[3] = {0.0, 0.0, 0.0};
	for (int i = 0; i < hull->vertexCount; ++i)
	{
		ref[0] += (double)hull->vertices[i].x;
		ref[1] += (double)hull->vertices[i].y;
		ref[2] += (double)hull->vertices[i].z;
	}
	for (int k = 0; k < 3; ++k)
	{
		ref[k] /= (double)hull->vertexCount;
	}
	/* For the tetrahedron (0, a, b, c): volume det / 6, first moment det / 24 (a + b + c), second
	 * moment integral of x x^T = det / 120 (a a^T + b b^T + c c^T + s s^T), s = a + b + c. */
	double volume6 = 0.0, first[3] = {0.0, 0.0, 0.0}, second[3][3] = {{0.0}};
	for (int f = 0; f < hull->faceCount; ++f)
	{
		int e0 = hull->faceEdges[f];
		cd3Vec v0 = hull->vertices[hull->edges[e0].origin];
		double a[3] = {(double)v0.x - ref[0], (double)v0.y - ref[1], (double)v0.z - ref[2]};
		for (int e = hull->edges[e0].next; hull->edges[e].next != e0; e = hull->edges[e].next)
		{
			cd3Vec v1 = hull->vertices[hull->edges[e].origin];
			cd3Vec v2 = hull->vertices[hull->edges[hull->edges[e].next].origin];
			double b[3] = {(double)v1.x - ref[0], (double)v1.y - ref[1], (double)v1.z - ref[2]};
			double c[3] = {(double)v2.x - ref[0], (double)v2.y - ref[1], (double)v2.z - ref[2]};
			double det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
						 a[2] * (b[0] * c[1] - b[1] * c[0]);
			double s[3] = {a[0] + b[0] + c[0], a[1] + b[1] + c[1], a[2] + b[2] + c[2]};
			volume6 += det;
			for (int i = 0; i < 3; ++i)
			{
				first[i] += det * s[i];
				for (int j = 0; j < 3; ++j)
				{
					second[i][j] += det * (a[i] * a[j] + b[i] * b[j] + c[i] * c[j] + s[i] * s[j]);
				}
			}
		}
	}
	double rho = (double)density;
	double volume = volume6 / 6.0;
	double mass = rho * volume;
	double com[3] = {0.0, 0.0, 0.0};
	if (volume6 > 0.0)
	{
		for (int i = 0; i < 3; ++i)
		{
			com[i] = first[i] / (4.0 * volume6);
		}
	}
	/* Second moment about the centre of mass (parallel axis), then I = tr(C) 1 - C. */
	double cov[3][3];
	for (int i = 0; i < 3; ++i)
	{
		for (int j = 0; j < 3; ++j)
		{
			cov[i][j] = rho * second[i][j] / 120.0 - mass * com[i] * com[j];
		}
	}
	double trace = cov[0][0] + cov[1][1] + cov[2][2];
	DMat local;
	for (int i = 0; i < 3; ++i)
	{
		for (int j = 0; j < 3; ++j)
		{
			local.m[i][j] = (i == j ? trace : 0.0) - cov[i][j];
		}
	}
	/* Into world axes: R I R^T. */
	cd3Quat u = cd3NormalizeQuat(shape.transform.q);
	double x = (double)u.x, y = (double)u.y, z = (double)u.z, w = (double)u.w;
	double r[3][3] = {{1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y)},
					  {2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x)},
					  {2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y)}};
	DMat world;
	for (int i = 0; i < 3; ++i)
	{
		for (int j = 0; j < 3; ++j)
		{
			double sum = 0.0;
			for (int k = 0; k < 3; ++k)
			{
				for (int l = 0; l < 3; ++l)
				{
					sum += r[i][k] * local.m[k][l] * r[j][l];
				}
			}
			world.m[i][j] = sum;
		}
	}
	cd3Vec centerLocal =
		cd3MakeVec((cdReal)(ref[0] + com[0]), (cdReal)(ref[1] + com[1]), (cdReal)(ref[2] + com[2]));
	cd3MassData data;
	data.mass = (cdReal)mass;
	data.center = cd3TransformPoint(shape.transform, centerLocal);
	data.inertia = ToMat(&world);
	return data;
}

/* Shapes without volume (the shape table's ComputeMass for them): zero mass at the centroid. */
static cd3MassData TriangleMass(cd3Triangle t, cdReal density)
{
	(void)density;
	return Zero(cd3Scale(CD_R(1.0) / CD_R(3.0), cd3Add(t.a, cd3Add(t.b, t.c))));
}

static cd3MassData SegmentMass(cd3Segment segment, cdReal density)
{
	(void)density;
	return Zero(cd3Lerp(segment.p1, segment.p2, CD_R(0.5)));
}

/* A half-space has no finite mass nor centroid: zero mass at the origin. */
static cd3MassData PlaneMass(cd3Plane plane, cdReal density)
{
	(void)plane;
	(void)density;
	return Zero(CD3_VEC_ZERO);
}

cd3MassData cd3ComputeShapeMass(const cd3Shape* shape, cdReal density)
{
	CD_ASSERT(shape != NULL);
	switch (shape->type)
	{
#define CD3_MASS_CASE(Name, PointIn, ClosestPointOn, Raycast, TypeName, Validate, ComputeAabb, ComputeMass,  \
					  ...)                                                                                   \
	case CD3_TYPE_##Name:                                                                                    \
		return ComputeMass(CD3_SHAPE_ARG(Name, shape), density);
		CD3_SHAPE_TABLE(CD3_MASS_CASE)
#undef CD3_MASS_CASE
		case CD3_SHAPE_TYPE_COUNT:
			break;
	}
	return Zero(CD3_VEC_ZERO);
}
