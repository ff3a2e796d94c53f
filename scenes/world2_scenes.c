#include "world2_scenes.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W2_TIME_STEP (CD_R(1.0) / CD_R(60.0))

static cd2Vec vec(cdReal x, cdReal y)
{
	cd2Vec v = {x, y};
	return v;
}

static cd2Rot rotIdentity(void)
{
	cd2Rot q = {CD_R(1.0), CD_R(0.0)};
	return q;
}

static cd2Polygon makeBox(cdReal hx, cdReal hy, cd2Vec center, cdReal angle)
{
	cd2Box box = {center, {hx, hy}, cd2MakeRot(angle)};
	cd2Polygon polygon;
	memset(&polygon, 0, sizeof(polygon));
	(void)cd2MakeBoxPolygon(box, &polygon);
	return polygon;
}

static cd2BodyId addBody(World2Scene* scene, const cd2BodyDef* def)
{
	cd2BodyId id = cd2CreateBody(scene->world, def);
	if (cd2IsNullBodyId(id))
	{
		scene->outOfMemory = true;
		return id;
	}
	if (scene->bodyCount == scene->bodyCapacity)
	{
		int capacity = scene->bodyCapacity < 256 ? 256 : 2 * scene->bodyCapacity;
		cd2BodyId* bodies = (cd2BodyId*)realloc(scene->bodies, (size_t)capacity * sizeof(cd2BodyId));
		if (bodies == NULL)
		{
			scene->outOfMemory = true;
			return id;
		}
		scene->bodies = bodies;
		scene->bodyCapacity = capacity;
	}
	scene->bodies[scene->bodyCount++] = id;
	return id;
}

static cd2BodyId addStatic(World2Scene* scene, cd2Vec position)
{
	cd2BodyDef def = cd2DefaultBodyDef();
	def.position = position;
	return addBody(scene, &def);
}

/* ---- Box2D v3's benchmark scenes ------------------------------------------------------------ */

/* large_pyramid's layout: unit boxes touching, on a 200 m x 2 m ground box under y = 0. */
static void createPyramid(World2Scene* scene, int baseCount)
{
	cd2World_EnableSleeping(scene->world, false);
	cd2BodyId ground = addStatic(scene, vec(0, CD_R(-1.0)));
	cd2ShapeDef groundShape = cd2DefaultShapeDef();
	cd2Polygon groundBox = makeBox(CD_R(100.0), CD_R(1.0), vec(0, 0), 0);
	cd2CreatePolygonShape(ground, &groundShape, &groundBox);

	cd2BodyDef def = cd2DefaultBodyDef();
	def.type = CD_DYNAMIC_BODY;
	cd2ShapeDef shape = cd2DefaultShapeDef();
	shape.density = CD_R(1.0);
	const cdReal a = CD_R(0.5);
	cd2Polygon box = makeBox(a, a, vec(0, 0), 0);
	for (int i = 0; i < baseCount; ++i)
	{
		cdReal y = (CD_R(2.0) * (cdReal)i + CD_R(1.0)) * a;
		for (int j = i; j < baseCount; ++j)
		{
			cdReal x = ((cdReal)i + CD_R(1.0)) * a + CD_R(2.0) * (cdReal)(j - i) * a - a * (cdReal)baseCount;
			def.position = vec(x, y);
			cd2CreatePolygonShape(addBody(scene, &def), &shape, &box);
		}
	}
}

/* many_pyramids: 20 x 20 pyramids of base 10 on 20 ground segments 11 m apart. */
static void createManyPyramids(World2Scene* scene)
{
	cd2World_EnableSleeping(scene->world, false);
	const int baseCount = 10, rowCount = 20, columnCount = 20;
	const cdReal extent = CD_R(0.5);
	cd2BodyId ground = addStatic(scene, vec(0, 0));
	cdReal groundDeltaY = CD_R(2.0) * extent * ((cdReal)baseCount + CD_R(1.0));
	cdReal groundWidth = CD_R(2.0) * extent * (cdReal)columnCount * ((cdReal)baseCount + CD_R(1.0));
	cd2ShapeDef shape = cd2DefaultShapeDef();
	cdReal groundY = 0;
	for (int i = 0; i < rowCount; ++i)
	{
		cd2Segment segment = {{CD_R(-0.5) * groundWidth, groundY}, {CD_R(0.5) * groundWidth, groundY}};
		cd2CreateSegmentShape(ground, &shape, &segment);
		groundY += groundDeltaY;
	}
	cdReal baseWidth = CD_R(2.0) * extent * (cdReal)baseCount;
	cdReal baseY = 0;
	cd2BodyDef def = cd2DefaultBodyDef();
	def.type = CD_DYNAMIC_BODY;
	cd2Polygon box = makeBox(extent, extent, vec(0, 0), 0);
	for (int row = 0; row < rowCount; ++row)
	{
		for (int column = 0; column < columnCount; ++column)
		{
			cdReal centerX = CD_R(-0.5) * groundWidth + (cdReal)column * (baseWidth + CD_R(2.0) * extent) +
							 CD_R(2.0) * extent;
			for (int i = 0; i < baseCount; ++i)
			{
				cdReal y = (CD_R(2.0) * (cdReal)i + CD_R(1.0)) * extent + baseY;
				for (int j = i; j < baseCount; ++j)
				{
					cdReal x = ((cdReal)i + CD_R(1.0)) * extent + CD_R(2.0) * (cdReal)(j - i) * extent +
							   centerX - CD_R(0.5);
					def.position = vec(x, y);
					cd2CreatePolygonShape(addBody(scene, &def), &shape, &box);
				}
			}
		}
		baseY += groundDeltaY;
	}
}

/* joint_grid: 100 x 100 discs linked by revolute joints, hanging from 7 static discs. */
static void createJointGrid(World2Scene* scene)
{
	cd2World_EnableSleeping(scene->world, false);
	const int n = 100;
	cd2BodyId* grid = (cd2BodyId*)malloc((size_t)(n * n) * sizeof(cd2BodyId));
	if (grid == NULL)
	{
		scene->outOfMemory = true;
		return;
	}
	cd2ShapeDef shape = cd2DefaultShapeDef();
	shape.density = CD_R(1.0);
	shape.filter.categoryBits = 2;
	shape.filter.maskBits = ~(uint64_t)2;
	cd2Circle circle = {{0, 0}, CD_R(0.4)};
	cd2RevoluteJointDef joint = cd2DefaultRevoluteJointDef();
	cd2BodyDef def = cd2DefaultBodyDef();
	int index = 0;
	for (int k = 0; k < n; ++k)
	{
		for (int i = 0; i < n; ++i)
		{
			def.type = (k >= n / 2 - 3 && k <= n / 2 + 3 && i == 0) ? CD_STATIC_BODY : CD_DYNAMIC_BODY;
			def.position = vec((cdReal)k, -(cdReal)i);
			cd2BodyId body = addBody(scene, &def);
			cd2CreateCircleShape(body, &shape, &circle);
			if (i > 0)
			{
				joint.bodyIdA = grid[index - 1];
				joint.bodyIdB = body;
				joint.localAnchorA = vec(0, CD_R(-0.5));
				joint.localAnchorB = vec(0, CD_R(0.5));
				cd2CreateRevoluteJoint(scene->world, &joint);
			}
			if (k > 0)
			{
				joint.bodyIdA = grid[index - n];
				joint.bodyIdB = body;
				joint.localAnchorA = vec(CD_R(0.5), 0);
				joint.localAnchorB = vec(CD_R(-0.5), 0);
				cd2CreateRevoluteJoint(scene->world, &joint);
			}
			grid[index++] = body;
		}
	}
	free(grid);
}

/* rain's ragdoll (Box2D's shared/human.c): 11 capsule bones from the hip, revolute joints with
 * limits, a friction motor (torque frictionTorque * bone scale) and a spring. One row per bone:
 * parent, body height, capsule (y1, y2, radius), pivot height, limits (x pi), friction scale,
 * linear damping, reference angle (x pi), foot. */
typedef struct HumanBone
{
	int parent;
	float y, y1, y2, radius, pivot, lower, upper, frictionScale, damping, reference;
	bool foot;
} HumanBone;

static const HumanBone humanBones[WORLD2_HUMAN_BONES] = {
	{-1, 0.95f, -0.02f, 0.02f, 0.095f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, false},		 /* hip */
	{0, 1.2f, -0.135f, 0.135f, 0.09f, 1.0f, -0.25f, 0.0f, 0.5f, 0.0f, 0.0f, false},		 /* torso */
	{1, 1.475f, -0.038f, 0.039f, 0.075f, 1.4f, -0.3f, 0.1f, 0.25f, 0.1f, 0.0f, false},	 /* head */
	{0, 0.775f, -0.125f, 0.125f, 0.06f, 0.9f, -0.05f, 0.4f, 1.0f, 0.0f, 0.0f, false},	 /* upper left leg */
	{3, 0.475f, -0.155f, 0.125f, 0.045f, 0.625f, -0.5f, -0.02f, 0.5f, 0.0f, 0.0f, true}, /* lower left leg */
	{0, 0.775f, -0.125f, 0.125f, 0.06f, 0.9f, -0.05f, 0.4f, 1.0f, 0.0f, 0.0f, false},	 /* upper right leg */
	{5, 0.475f, -0.155f, 0.125f, 0.045f, 0.625f, -0.5f, -0.02f, 0.5f, 0.0f, 0.0f, true}, /* lower right leg */
	{1, 1.225f, -0.125f, 0.125f, 0.035f, 1.35f, -0.1f, 0.8f, 0.5f, 0.0f, 0.0f, false},	 /* upper left arm */
	{7, 0.975f, -0.125f, 0.125f, 0.03f, 1.1f, -0.2f, 0.3f, 0.1f, 0.1f, 0.25f, false},	 /* lower left arm */
	{1, 1.225f, -0.125f, 0.125f, 0.035f, 1.35f, -0.1f, 0.8f, 0.5f, 0.0f, 0.0f, false},	 /* upper right arm */
	{9, 0.975f, -0.125f, 0.125f, 0.03f, 1.1f, -0.2f, 0.3f, 0.1f, 0.1f, 0.25f, false},	 /* lower right arm */
};

static void createHuman(World2Scene* scene, World2Human* human, cd2Vec position, cdReal frictionTorque,
						cdReal hertz, cdReal dampingRatio, int groupIndex)
{
	cd2BodyDef def = cd2DefaultBodyDef();
	def.type = CD_DYNAMIC_BODY;
	def.sleepThreshold = CD_R(0.1);
	cd2ShapeDef shape = cd2DefaultShapeDef();
	shape.friction = CD_R(0.2);
	shape.filter.groupIndex = -groupIndex;
	shape.filter.categoryBits = 2;
	shape.filter.maskBits = 1 | 2;
	cd2ShapeDef footShape = shape;
	footShape.friction = CD_R(0.05);
	footShape.filter.maskBits = 1; /* feet do not touch ragdolls */
	cd2Vec footPoints[4] = {{CD_R(-0.03), CD_R(-0.185)},
							{CD_R(0.11), CD_R(-0.185)},
							{CD_R(0.11), CD_R(-0.16)},
							{CD_R(-0.03), CD_R(-0.14)}};
	cd2Polygon foot;
	memset(&foot, 0, sizeof(foot));
	(void)cd2MakeRoundedPolygon(footPoints, 4, CD_R(0.015), &foot);
	for (int i = 0; i < WORLD2_HUMAN_BONES; ++i)
	{
		const HumanBone* bone = &humanBones[i];
		def.position = vec(position.x, position.y + (cdReal)bone->y);
		def.linearDamping = (cdReal)bone->damping;
		cd2BodyId body = addBody(scene, &def);
		human->bodies[i] = body;
		human->joints[i] = CD2_NULL_JOINT_ID;
		cd2Capsule capsule = {{0, (cdReal)bone->y1}, {0, (cdReal)bone->y2}, (cdReal)bone->radius};
		cd2CreateCapsuleShape(body, &shape, &capsule);
		if (bone->foot)
		{
			cd2CreatePolygonShape(body, &footShape, &foot);
		}
		if (bone->parent < 0)
		{
			continue;
		}
		cd2Vec pivot = vec(position.x, position.y + (cdReal)bone->pivot);
		cd2RevoluteJointDef joint = cd2DefaultRevoluteJointDef();
		joint.bodyIdA = human->bodies[bone->parent];
		joint.bodyIdB = body;
		joint.localAnchorA = cd2Body_GetLocalPoint(joint.bodyIdA, pivot);
		joint.localAnchorB = cd2Body_GetLocalPoint(joint.bodyIdB, pivot);
		joint.referenceAngle = (cdReal)bone->reference * CD_PI;
		joint.enableLimit = true;
		joint.lowerAngle = (cdReal)bone->lower * CD_PI;
		joint.upperAngle = (cdReal)bone->upper * CD_PI;
		joint.enableMotor = true;
		joint.maxMotorTorque = (cdReal)bone->frictionScale * frictionTorque;
		joint.enableSpring = hertz > 0;
		joint.hertz = hertz;
		joint.dampingRatio = dampingRatio;
		human->joints[i] = cd2CreateRevoluteJoint(scene->world, &joint);
	}
	human->spawned = true;
}

static void destroyHuman(World2Human* human)
{
	for (int i = 0; i < WORLD2_HUMAN_BONES; ++i)
	{
		if (!cd2IsNullJointId(human->joints[i]) && cd2Joint_IsValid(human->joints[i]))
		{
			cd2DestroyJoint(human->joints[i]);
		}
		human->joints[i] = CD2_NULL_JOINT_ID;
	}
	for (int i = 0; i < WORLD2_HUMAN_BONES; ++i)
	{
		if (cd2Body_IsValid(human->bodies[i]))
		{
			cd2DestroyBody(human->bodies[i]);
		}
		human->bodies[i] = CD2_NULL_BODY_ID;
	}
	human->spawned = false;
}

static const cdReal rainGridSize = CD_R(0.5);
static const int rainGridCount = 500;

static void createRain(World2Scene* scene)
{
	scene->rain =
		(World2Human*)calloc(WORLD2_RAIN_ROWS * WORLD2_RAIN_COLUMNS * WORLD2_RAIN_GROUP, sizeof(World2Human));
	if (scene->rain == NULL)
	{
		scene->outOfMemory = true;
		return;
	}
	cd2BodyId ground = addStatic(scene, vec(0, 0));
	cd2ShapeDef shape = cd2DefaultShapeDef();
	cdReal y = 0;
	for (int i = 0; i < WORLD2_RAIN_ROWS; ++i)
	{
		cdReal x = CD_R(-0.5) * (cdReal)rainGridCount * rainGridSize;
		for (int j = 0; j <= rainGridCount; ++j)
		{
			cd2Polygon box = makeBox(CD_R(0.5) * rainGridSize, CD_R(0.5) * rainGridSize, vec(x, y), 0);
			cd2CreatePolygonShape(ground, &shape, &box);
			x += rainGridSize;
		}
		y += CD_R(45.0);
	}
}

static void createRainGroup(World2Scene* scene, int row, int column)
{
	cdReal span = (cdReal)rainGridCount * rainGridSize;
	cdReal groupDistance = span / (cdReal)WORLD2_RAIN_COLUMNS;
	cd2Vec position = vec(CD_R(-0.5) * span + groupDistance * ((cdReal)column + CD_R(0.5)),
						  CD_R(40.0) + CD_R(45.0) * (cdReal)row);
	World2Human* group = scene->rain + (row * WORLD2_RAIN_COLUMNS + column) * WORLD2_RAIN_GROUP;
	for (int i = 0; i < WORLD2_RAIN_GROUP; ++i)
	{
		createHuman(scene, group + i, position, CD_R(0.05), CD_R(5.0), CD_R(0.5), i + 1);
		position.x += CD_R(0.5);
	}
}

static void stepRain(World2Scene* scene, int stepIndex)
{
	if ((stepIndex & 7) != 0 || scene->rain == NULL)
	{
		return;
	}
	if (scene->rainColumnCount < WORLD2_RAIN_COLUMNS)
	{
		for (int row = 0; row < WORLD2_RAIN_ROWS; ++row)
		{
			createRainGroup(scene, row, scene->rainColumnCount);
		}
		scene->rainColumnCount += 1;
	}
	else
	{
		for (int row = 0; row < WORLD2_RAIN_ROWS; ++row)
		{
			World2Human* group =
				scene->rain + (row * WORLD2_RAIN_COLUMNS + scene->rainColumnIndex) * WORLD2_RAIN_GROUP;
			for (int i = 0; i < WORLD2_RAIN_GROUP; ++i)
			{
				destroyHuman(group + i);
			}
			createRainGroup(scene, row, scene->rainColumnIndex);
		}
		scene->rainColumnIndex = (scene->rainColumnIndex + 1) % WORLD2_RAIN_COLUMNS;
	}
}

/* spinner: a 360-point chain loop (radius 40 around (0, 32)) and a motorized rounded bar of
 * 40 m inside it, stirring 6076 capsules, discs and squares. */
static void createSpinner(World2Scene* scene)
{
	enum
	{
		POINT_COUNT = 360
	};
	cd2BodyId ground = addStatic(scene, vec(0, 0));
	cd2Vec points[POINT_COUNT];
	cd2Rot q = cd2MakeRot(CD_R(-2.0) * CD_PI / (cdReal)POINT_COUNT);
	cd2Vec p = vec(CD_R(40.0), 0);
	for (int i = 0; i < POINT_COUNT; ++i)
	{
		points[i] = vec(p.x, p.y + CD_R(32.0));
		p = cd2RotateVector(q, p);
	}
	cd2ChainDef chain = cd2DefaultChainDef();
	chain.points = points;
	chain.count = POINT_COUNT;
	chain.isLoop = true;
	chain.friction = CD_R(0.1);
	cd2CreateChainShape(ground, &chain);

	cd2BodyDef def = cd2DefaultBodyDef();
	def.type = CD_DYNAMIC_BODY;
	def.position = vec(0, CD_R(12.0));
	def.enableSleep = false;
	cd2BodyId spinner = addBody(scene, &def);
	cd2Box bar = {{0, 0}, {CD_R(0.4), CD_R(20.0)}, rotIdentity()};
	cd2Polygon barPolygon;
	memset(&barPolygon, 0, sizeof(barPolygon));
	(void)cd2MakeRoundedBoxPolygon(bar, CD_R(0.2), &barPolygon);
	cd2ShapeDef barShape = cd2DefaultShapeDef();
	barShape.friction = 0;
	cd2CreatePolygonShape(spinner, &barShape, &barPolygon);
	cd2RevoluteJointDef joint = cd2DefaultRevoluteJointDef();
	joint.bodyIdA = ground;
	joint.bodyIdB = spinner;
	joint.localAnchorA = cd2Body_GetLocalPoint(ground, def.position);
	joint.localAnchorB = vec(0, 0);
	joint.enableMotor = true;
	joint.motorSpeed = CD_R(5.0);
	joint.maxMotorTorque = (cdReal)FLT_MAX;
	scene->spinnerJoint = cd2CreateRevoluteJoint(scene->world, &joint);

	cd2Capsule capsule = {{CD_R(-0.25), 0}, {CD_R(0.25), 0}, CD_R(0.25)};
	cd2Circle circle = {{0, 0}, CD_R(0.35)};
	cd2Polygon square = makeBox(CD_R(0.35), CD_R(0.35), vec(0, 0), 0);
	cd2BodyDef bodyDef = cd2DefaultBodyDef();
	bodyDef.type = CD_DYNAMIC_BODY;
	cd2ShapeDef shape = cd2DefaultShapeDef();
	shape.friction = CD_R(0.1);
	shape.restitution = CD_R(0.1);
	shape.density = CD_R(0.25);
	const int bodyCount = 2 * 3038;
	cdReal x = CD_R(-23.0), y = CD_R(2.0);
	for (int i = 0; i < bodyCount; ++i)
	{
		bodyDef.position = vec(x, y);
		cd2BodyId body = addBody(scene, &bodyDef);
		if (i % 3 == 0)
		{
			cd2CreateCapsuleShape(body, &shape, &capsule);
		}
		else if (i % 3 == 1)
		{
			cd2CreateCircleShape(body, &shape, &circle);
		}
		else
		{
			cd2CreatePolygonShape(body, &shape, &square);
		}
		x += CD_R(0.5);
		if (x >= CD_R(23.0))
		{
			x = CD_R(-23.0);
			y += CD_R(0.5);
		}
	}
}

/* smash: no gravity; an 8 m box of density 8 at 40 m/s into 120 x 80 sleeping 0.4 m boxes. */
static void createSmash(World2Scene* scene)
{
	cd2World_SetGravity(scene->world, vec(0, 0));
	cd2BodyDef def = cd2DefaultBodyDef();
	def.type = CD_DYNAMIC_BODY;
	def.position = vec(CD_R(-20.0), 0);
	def.linearVelocity = vec(CD_R(40.0), 0);
	cd2ShapeDef shape = cd2DefaultShapeDef();
	shape.density = CD_R(8.0);
	cd2Polygon big = makeBox(CD_R(4.0), CD_R(4.0), vec(0, 0), 0);
	cd2CreatePolygonShape(addBody(scene, &def), &shape, &big);

	const cdReal d = CD_R(0.4);
	cd2Polygon box = makeBox(CD_R(0.5) * d, CD_R(0.5) * d, vec(0, 0), 0);
	cd2BodyDef small = cd2DefaultBodyDef();
	small.type = CD_DYNAMIC_BODY;
	small.isAwake = false;
	cd2ShapeDef smallShape = cd2DefaultShapeDef();
	const int columns = 120, rows = 80;
	for (int i = 0; i < columns; ++i)
	{
		for (int j = 0; j < rows; ++j)
		{
			small.position = vec((cdReal)i * d + CD_R(30.0), ((cdReal)j - (cdReal)rows / CD_R(2.0)) * d);
			cd2CreatePolygonShape(addBody(scene, &small), &smallShape, &box);
		}
	}
}

/* tumbler: a 20 m box drum (density 50) turned at 25 deg/s by a revolute motor, 45 x 45 small boxes. */
static void createTumbler(World2Scene* scene)
{
	cd2BodyId ground = addStatic(scene, vec(0, 0));
	cd2BodyDef def = cd2DefaultBodyDef();
	def.type = CD_DYNAMIC_BODY;
	def.position = vec(0, CD_R(10.0));
	cd2BodyId drum = addBody(scene, &def);
	cd2ShapeDef shape = cd2DefaultShapeDef();
	shape.density = CD_R(50.0);
	cd2Polygon wall;
	wall = makeBox(CD_R(0.5), CD_R(10.0), vec(CD_R(10.0), 0), 0);
	cd2CreatePolygonShape(drum, &shape, &wall);
	wall = makeBox(CD_R(0.5), CD_R(10.0), vec(CD_R(-10.0), 0), 0);
	cd2CreatePolygonShape(drum, &shape, &wall);
	wall = makeBox(CD_R(10.0), CD_R(0.5), vec(0, CD_R(10.0)), 0);
	cd2CreatePolygonShape(drum, &shape, &wall);
	wall = makeBox(CD_R(10.0), CD_R(0.5), vec(0, CD_R(-10.0)), 0);
	cd2CreatePolygonShape(drum, &shape, &wall);
	cd2RevoluteJointDef joint = cd2DefaultRevoluteJointDef();
	joint.bodyIdA = ground;
	joint.bodyIdB = drum;
	joint.localAnchorA = vec(0, CD_R(10.0));
	joint.localAnchorB = vec(0, 0);
	joint.motorSpeed = (CD_PI / CD_R(180.0)) * CD_R(25.0);
	joint.maxMotorTorque = CD_R(1e8);
	joint.enableMotor = true;
	cd2CreateRevoluteJoint(scene->world, &joint);

	const int gridCount = 45;
	cd2Polygon box = makeBox(CD_R(0.125), CD_R(0.125), vec(0, 0), 0);
	cd2BodyDef boxDef = cd2DefaultBodyDef();
	boxDef.type = CD_DYNAMIC_BODY;
	cd2ShapeDef boxShape = cd2DefaultShapeDef();
	cdReal y = CD_R(-0.2) * (cdReal)gridCount + CD_R(10.0);
	for (int i = 0; i < gridCount; ++i)
	{
		cdReal x = CD_R(-0.2) * (cdReal)gridCount;
		for (int j = 0; j < gridCount; ++j)
		{
			boxDef.position = vec(x, y);
			cd2CreatePolygonShape(addBody(scene, &boxDef), &boxShape, &box);
			x += CD_R(0.4);
		}
		y += CD_R(0.4);
	}
}

/* ---- collide's own scenes ------------------------------------------------------------------ */

static cd2BodyId addGroundBox(World2Scene* scene, cdReal x0, cdReal x1, cdReal top)
{
	cd2BodyId ground = addStatic(scene, vec(0, 0));
	cd2ShapeDef shape = cd2DefaultShapeDef();
	cd2Polygon box =
		makeBox(CD_R(0.5) * (x1 - x0), CD_R(0.5), vec(CD_R(0.5) * (x0 + x1), top - CD_R(0.5)), 0);
	cd2CreatePolygonShape(ground, &shape, &box);
	return ground;
}

/* card_house: cards 1 m x 2 cm, friction 0.7; three floors of leaning pairs (20 degrees from the
 * vertical, tops touching) with flat cards bridging neighbouring pairs. */
static void createCardHouse(World2Scene* scene)
{
	(void)addGroundBox(scene, CD_R(-20.0), CD_R(20.0), 0);
	const cdReal h = CD_R(0.5), t = CD_R(0.01), lean = CD_R(20.0) * CD_PI / CD_R(180.0);
	const cdReal spacing = CD_R(0.8);
	const cdReal sinLean = (cdReal)sin((double)lean), cosLean = (cdReal)cos((double)lean);
	const cdReal frameHeight = CD_R(2.0) * h * cosLean + CD_R(2.0) * t * sinLean;
	cd2Polygon card = makeBox(t, h, vec(0, 0), 0);
	cd2BodyDef def = cd2DefaultBodyDef();
	def.type = CD_DYNAMIC_BODY;
	cd2ShapeDef shape = cd2DefaultShapeDef();
	shape.friction = CD_R(0.7);
	cdReal floorY = 0;
	for (int floor = 0; floor < 3; ++floor)
	{
		int frames = 3 - floor;
		cdReal x0 = -CD_R(0.5) * spacing * (cdReal)(frames - 1);
		for (int f = 0; f < frames; ++f)
		{
			cdReal cx = x0 + spacing * (cdReal)f;
			/* Each card's axis runs from its foot to the apex cx; moved out by its half thickness. */
			cdReal offset = t / cosLean;
			def.position = vec(cx - h * sinLean - offset, floorY + h * cosLean + t * sinLean);
			def.rotation = cd2MakeRot(-lean);
			cd2CreatePolygonShape(addBody(scene, &def), &shape, &card);
			def.position = vec(cx + h * sinLean + offset, floorY + h * cosLean + t * sinLean);
			def.rotation = cd2MakeRot(lean);
			cd2CreatePolygonShape(addBody(scene, &def), &shape, &card);
		}
		if (floor == 2)
		{
			break;
		}
		for (int f = 0; f + 1 < frames; ++f)
		{
			cdReal cx = x0 + spacing * ((cdReal)f + CD_R(0.5));
			def.position = vec(cx, floorY + frameHeight + t);
			def.rotation = cd2MakeRot(CD_R(0.5) * CD_PI);
			cd2CreatePolygonShape(addBody(scene, &def), &shape, &card);
		}
		floorY += frameHeight + CD_R(2.0) * t;
	}
}

/* ramp: friction 0.5 everywhere; a 1 m block resting on a 20-degree ramp (x < 0) and one on a
 * 40-degree ramp (x > 0), both ramps 16 m long. */
static void createRamp(World2Scene* scene)
{
	cd2ShapeDef shape = cd2DefaultShapeDef();
	shape.friction = (cdReal)WORLD2_RAMP_FRICTION;
	const double angles[2] = {WORLD2_RAMP_GENTLE_DEGREES, WORLD2_RAMP_STEEP_DEGREES};
	const cdReal centers[2] = {CD_R(-15.0), CD_R(15.0)};
	const cdReal along[2] = {0, CD_R(5.0)}; /* where the block starts along the ramp */
	for (int i = 0; i < 2; ++i)
	{
		cdReal angle = (cdReal)(angles[i] * 3.14159265358979323846 / 180.0);
		cd2Vec tangent = vec((cdReal)cos((double)angle), (cdReal)sin((double)angle));
		cd2Vec normal = vec(-tangent.y, tangent.x);
		cd2BodyId ramp = addStatic(scene, vec(centers[i], 0));
		cd2Polygon slab = makeBox(CD_R(8.0), CD_R(0.25), vec(0, 0), angle);
		cd2CreatePolygonShape(ramp, &shape, &slab);
		cd2BodyDef def = cd2DefaultBodyDef();
		def.type = CD_DYNAMIC_BODY;
		def.position = vec(centers[i] + along[i] * tangent.x + CD_R(0.75) * normal.x,
						   along[i] * tangent.y + CD_R(0.75) * normal.y);
		def.rotation = cd2MakeRot(angle);
		cd2Polygon block = makeBox(CD_R(0.5), CD_R(0.5), vec(0, 0), 0);
		cd2CreatePolygonShape(addBody(scene, &def), &shape, &block);
	}
}

/* bullets: no gravity; 20 discs of 0.1 m flagged as bullets at 300-1000 m/s against a static wall
 * 0.1 m thick and 10 m high centred on x = 0. */
static void createBullets(World2Scene* scene)
{
	cd2World_SetGravity(scene->world, vec(0, 0));
	cd2BodyId wall = addStatic(scene, vec(0, CD_R(5.0)));
	cd2ShapeDef shape = cd2DefaultShapeDef();
	cd2Polygon box = makeBox((cdReal)WORLD2_BULLET_WALL_X, CD_R(5.0), vec(0, 0), 0);
	cd2CreatePolygonShape(wall, &shape, &box);
	cd2Circle circle = {{0, 0}, CD_R(0.05)};
	cd2BodyDef def = cd2DefaultBodyDef();
	def.type = CD_DYNAMIC_BODY;
	def.isBullet = true;
	for (int i = 0; i < 20; ++i)
	{
		cdReal speed = CD_R(300.0) + CD_R(700.0) * (cdReal)i / CD_R(19.0);
		def.position = vec(CD_R(-20.0) - CD_R(0.37) * (cdReal)i, CD_R(0.5) + CD_R(0.45) * (cdReal)i);
		def.linearVelocity = vec(speed, CD_R(0.01) * speed * (cdReal)((i % 3) - 1));
		cd2CreateCircleShape(addBody(scene, &def), &shape, &circle);
	}
}

/* side_scroller's one-way platform: contacts with it hold only from above (normal from the
 * platform to the other shape pointing up, and not yet sunk in). */
static bool oneWayPreSolve(cd2ShapeId shapeIdA, cd2ShapeId shapeIdB, const cd2Manifold* manifold,
						   void* context)
{
	const World2Scene* scene = (const World2Scene*)context;
	cdReal sign;
	if (cd2ShapeIdEqual(shapeIdA, scene->oneWayShape))
	{
		sign = CD_R(1.0);
	}
	else if (cd2ShapeIdEqual(shapeIdB, scene->oneWayShape))
	{
		sign = CD_R(-1.0);
	}
	else
	{
		return true;
	}
	if (sign * manifold->normal.y < CD_R(0.7))
	{
		return false;
	}
	for (int i = 0; i < manifold->pointCount; ++i)
	{
		if (manifold->points[i].separation < CD_R(-0.05))
		{
			return false;
		}
	}
	return true;
}

/* Ground from x = -5 to 30 and 34 to 90 (top y = 0), the pit between them bridged by a 5 m
 * kinematic platform swinging +-0.5 m; a one-way platform (x 20-26, top 2 m), a static ledge
 * (x 44-50, 3 m up); pick-ups at x = 5, 15, 25 (above the one-way platform), 35, 45; a capsule
 * character walking at 5 m/s
 * that jumps once at x = 17.5 onto the one-way platform and stops at x = 70. */
static void createSideScroller(World2Scene* scene)
{
	(void)addGroundBox(scene, CD_R(-5.0), CD_R(30.0), 0);
	(void)addGroundBox(scene, CD_R(34.0), CD_R(90.0), 0);
	(void)addGroundBox(scene, CD_R(25.0), CD_R(40.0), CD_R(-10.0)); /* the pit's floor */
	cd2ShapeDef shape = cd2DefaultShapeDef();

	cd2BodyId ledge = addStatic(scene, vec(CD_R(47.0), CD_R(2.9)));
	cd2Polygon ledgeBox = makeBox(CD_R(3.0), CD_R(0.1), vec(0, 0), 0);
	cd2CreatePolygonShape(ledge, &shape, &ledgeBox);

	cd2BodyId oneWay = addStatic(scene, vec(CD_R(23.0), CD_R(1.9)));
	cd2Polygon oneWayBox = makeBox(CD_R(3.0), CD_R(0.1), vec(0, 0), 0);
	cd2ShapeDef oneWayShape = shape;
	oneWayShape.enablePreSolveEvents = true;
	scene->oneWayShape = cd2CreatePolygonShape(oneWay, &oneWayShape, &oneWayBox);
	cd2World_SetPreSolveCallback(scene->world, oneWayPreSolve, scene);

	cd2BodyDef moverDef = cd2DefaultBodyDef();
	moverDef.type = CD_KINEMATIC_BODY;
	moverDef.position = vec(CD_R(32.0), CD_R(-0.15));
	scene->mover = addBody(scene, &moverDef);
	cd2Polygon moverBox = makeBox(CD_R(2.5), CD_R(0.15), vec(0, 0), 0);
	cd2CreatePolygonShape(scene->mover, &shape, &moverBox);

	cd2ShapeDef sensor = cd2DefaultShapeDef();
	sensor.isSensor = true;
	sensor.enableSensorEvents = true;
	cd2Circle pickup = {{0, 0}, CD_R(0.3)};
	for (int i = 0; i < WORLD2_PICKUPS; ++i)
	{
		/* The third is above the one-way platform, on the character's way across it. */
		cdReal y = i == 2 ? CD_R(3.0) : CD_R(1.0);
		cd2BodyId body = addStatic(scene, vec(CD_R(5.0) + CD_R(10.0) * (cdReal)i, y));
		scene->pickups[i] = cd2CreateCircleShape(body, &sensor, &pickup);
	}

	cd2BodyDef def = cd2DefaultBodyDef();
	def.type = CD_DYNAMIC_BODY;
	def.position = vec(0, CD_R(0.8));
	def.fixedRotation = true;
	def.enableSleep = false;
	scene->character = addBody(scene, &def);
	cd2ShapeDef body = cd2DefaultShapeDef();
	body.friction = CD_R(0.0);
	body.enableSensorEvents = true;
	cd2Capsule capsule = {{0, CD_R(-0.5)}, {0, CD_R(0.5)}, CD_R(0.3)};
	scene->characterShape = cd2CreateCapsuleShape(scene->character, &body, &capsule);
	scene->lowestCharacterY = 1e30;
}

static void stepSideScroller(World2Scene* scene, int stepIndex)
{
	/* The moving platform: x = 32 + 0.5 sin(t), as a velocity. */
	cdReal t = (cdReal)stepIndex * W2_TIME_STEP;
	cd2Body_SetLinearVelocity(scene->mover, vec(CD_R(0.5) * (cdReal)cos((double)t), 0));
	cd2Vec p = cd2Body_GetPosition(scene->character);
	cd2Vec v = cd2Body_GetLinearVelocity(scene->character);
	v.x = p.x < CD_R(70.0) ? CD_R(5.0) : 0;
	if (!scene->jumped && p.x > CD_R(17.5))
	{
		v.y = CD_R(7.0);
		scene->jumped = true;
	}
	cd2Body_SetLinearVelocity(scene->character, v);
	if (p.x > CD_R(21.0) && p.x < CD_R(25.0) && p.y > CD_R(2.7) && p.y < CD_R(2.95) && cdAbs(v.y) < CD_R(0.5))
	{
		scene->landedOnOneWay = true;
	}
	scene->lowestCharacterY = (double)p.y < scene->lowestCharacterY ? (double)p.y : scene->lowestCharacterY;
}

static void countPickups(World2Scene* scene)
{
	cd2SensorEvents events = cd2World_GetSensorEvents(scene->world);
	for (int i = 0; i < WORLD2_PICKUPS; ++i)
	{
		for (int e = 0; e < events.beginCount; ++e)
		{
			if (cd2ShapeIdEqual(events.beginEvents[e].sensorShapeId, scene->pickups[i]) &&
				cd2ShapeIdEqual(events.beginEvents[e].visitorShapeId, scene->characterShape))
			{
				scene->pickupBegin[i] += 1;
			}
		}
		for (int e = 0; e < events.endCount; ++e)
		{
			if (cd2ShapeIdEqual(events.endEvents[e].sensorShapeId, scene->pickups[i]) &&
				cd2ShapeIdEqual(events.endEvents[e].visitorShapeId, scene->characterShape))
			{
				scene->pickupEnd[i] += 1;
			}
		}
	}
}

/* Pendulum chains released from horizontal (world2_quality.h): the energy the solver keeps. */
static void createChains(World2Scene* scene)
{
	cd2World_EnableSleeping(scene->world, false);
	cdReal length = (cdReal)WORLD2_CHAIN_LINK_LENGTH;
	cd2Capsule capsule = {
		{CD_R(-0.5) * length, 0}, {CD_R(0.5) * length, 0}, (cdReal)WORLD2_CHAIN_LINK_RADIUS};
	cd2ShapeDef shape = cd2DefaultShapeDef();
	shape.density = CD_R(1.0);
	shape.filter.groupIndex = -1; /* the links never collide */
	for (int k = 0; k < WORLD2_CHAIN_COUNT; ++k)
	{
		cdReal x0 = (cdReal)(WORLD2_CHAIN_SPACING * (double)k);
		cd2BodyId previous = addStatic(scene, vec(x0, 0));
		for (int i = 0; i < world2ChainLinks(k); ++i)
		{
			cd2BodyDef def = cd2DefaultBodyDef();
			def.type = CD_DYNAMIC_BODY;
			def.position = vec(x0 + length * ((cdReal)i + CD_R(0.5)), 0);
			cd2BodyId link = addBody(scene, &def);
			cd2CreateCapsuleShape(link, &shape, &capsule);
			cd2RevoluteJointDef joint = cd2DefaultRevoluteJointDef();
			joint.bodyIdA = previous;
			joint.bodyIdB = link;
			joint.localAnchorA = i == 0 ? vec(0, 0) : vec(CD_R(0.5) * length, 0);
			joint.localAnchorB = vec(CD_R(-0.5) * length, 0);
			cd2CreateRevoluteJoint(scene->world, &joint);
			previous = link;
		}
	}
}
/* slingshot: a 0.3 m disc of density 5 shot at (30, 8) m/s from (0, 1) into two towers of pillars
 * and planks (x 20 and 24) and a rope bridge of 8 planks between two posts (x 30 to 34), on a
 * ground 410 m long (the light blocks fly far). */
static void createSlingshot(World2Scene* scene)
{
	(void)addGroundBox(scene, CD_R(-10.0), CD_R(400.0), 0);
	cd2BodyDef def = cd2DefaultBodyDef();
	def.type = CD_DYNAMIC_BODY;
	cd2ShapeDef shape = cd2DefaultShapeDef();
	shape.density = CD_R(0.5);
	shape.friction = CD_R(0.6);
	cd2Polygon pillar = makeBox(CD_R(0.15), CD_R(0.6), vec(0, 0), 0);
	cd2Polygon plank = makeBox(CD_R(1.0), CD_R(0.1), vec(0, 0), 0);
	for (int tower = 0; tower < 2; ++tower)
	{
		cdReal cx = CD_R(20.0) + CD_R(4.0) * (cdReal)tower;
		cdReal y = 0;
		for (int level = 0; level < 3; ++level)
		{
			def.position = vec(cx - CD_R(0.8), y + CD_R(0.6));
			cd2CreatePolygonShape(addBody(scene, &def), &shape, &pillar);
			def.position = vec(cx + CD_R(0.8), y + CD_R(0.6));
			cd2CreatePolygonShape(addBody(scene, &def), &shape, &pillar);
			def.position = vec(cx, y + CD_R(1.3));
			cd2CreatePolygonShape(addBody(scene, &def), &shape, &plank);
			y += CD_R(1.4);
		}
	}

	/* The bridge: posts 3 m high, 8 planks of 0.5 m joined end to end by revolute joints. */
	cd2BodyId left = addStatic(scene, vec(CD_R(30.0), CD_R(1.5)));
	cd2BodyId right = addStatic(scene, vec(CD_R(34.0), CD_R(1.5)));
	cd2Polygon post = makeBox(CD_R(0.1), CD_R(1.5), vec(0, 0), 0);
	cd2ShapeDef postShape = cd2DefaultShapeDef();
	cd2CreatePolygonShape(left, &postShape, &post);
	cd2CreatePolygonShape(right, &postShape, &post);
	cd2Polygon link = makeBox(CD_R(0.25), CD_R(0.05), vec(0, 0), 0);
	cd2BodyId previous = left;
	cd2Vec previousAnchor = vec(0, CD_R(1.5));
	scene->bridgeJointCount = 0;
	for (int i = 0; i <= 8; ++i)
	{
		cd2BodyId next = right;
		cd2Vec nextAnchor = vec(0, CD_R(1.5));
		if (i < 8)
		{
			def.position = vec(CD_R(30.25) + CD_R(0.5) * (cdReal)i, CD_R(3.0));
			next = addBody(scene, &def);
			cd2CreatePolygonShape(next, &shape, &link);
			nextAnchor = vec(CD_R(-0.25), 0);
		}
		cd2RevoluteJointDef joint = cd2DefaultRevoluteJointDef();
		joint.bodyIdA = previous;
		joint.bodyIdB = next;
		joint.localAnchorA = previousAnchor;
		joint.localAnchorB = nextAnchor;
		scene->bridgeJoints[scene->bridgeJointCount] = cd2CreateRevoluteJoint(scene->world, &joint);
		scene->bridgeAnchorA[scene->bridgeJointCount] = previousAnchor;
		scene->bridgeAnchorB[scene->bridgeJointCount] = nextAnchor;
		scene->bridgeJointCount += 1;
		previous = next;
		previousAnchor = vec(CD_R(0.25), 0);
	}
	/* A target on the bridge. */
	def.position = vec(CD_R(32.0), CD_R(3.35));
	cd2Polygon target = makeBox(CD_R(0.3), CD_R(0.3), vec(0, 0), 0);
	cd2CreatePolygonShape(addBody(scene, &def), &shape, &target);

	cd2BodyDef shot = cd2DefaultBodyDef();
	shot.type = CD_DYNAMIC_BODY;
	shot.position = vec(0, CD_R(1.0));
	shot.linearVelocity = vec(CD_R(30.0), CD_R(8.0));
	shot.isBullet = true;
	cd2ShapeDef shotShape = cd2DefaultShapeDef();
	shotShape.density = CD_R(5.0);
	cd2Circle ball = {{0, 0}, CD_R(0.3)};
	cd2CreateCircleShape(addBody(scene, &shot), &shotShape, &ball);
}

/* ---- the scene interface ------------------------------------------------------------------- */

bool world2SceneCreate(World2Scene* scene, World2SceneId id, int workerCount)
{
	memset(scene, 0, sizeof(*scene));
	scene->id = id;
	const World2SceneInfo* info = world2SceneInfo(id);
	if (info == NULL)
	{
		return false;
	}
	cd2WorldDef def = cd2DefaultWorldDef();
	def.workerCount = workerCount;
	if (id == WORLD2_BULLETS)
	{
		def.maximumLinearSpeed = CD_R(2000.0);
	}
	scene->world = cd2CreateWorld(&def);
	if (!cd2World_IsValid(scene->world))
	{
		return false;
	}
	switch (id)
	{
		case WORLD2_PYRAMID_20:
			createPyramid(scene, 20);
			break;
		case WORLD2_PYRAMID_40:
			createPyramid(scene, 40);
			break;
		case WORLD2_LARGE_PYRAMID:
			createPyramid(scene, 100);
			break;
		case WORLD2_MANY_PYRAMIDS:
			createManyPyramids(scene);
			break;
		case WORLD2_JOINT_GRID:
			createJointGrid(scene);
			break;
		case WORLD2_RAIN:
			createRain(scene);
			break;
		case WORLD2_SMASH:
			createSmash(scene);
			break;
		case WORLD2_SPINNER:
			createSpinner(scene);
			break;
		case WORLD2_TUMBLER:
			createTumbler(scene);
			break;
		case WORLD2_CARD_HOUSE:
			createCardHouse(scene);
			break;
		case WORLD2_RAMP:
			createRamp(scene);
			break;
		case WORLD2_BULLETS:
			createBullets(scene);
			break;
		case WORLD2_SIDE_SCROLLER:
			createSideScroller(scene);
			break;
		case WORLD2_SLINGSHOT:
			createSlingshot(scene);
			break;
		case WORLD2_CHAINS:
			createChains(scene);
			break;
		default:
			break;
	}
	if (scene->outOfMemory)
	{
		world2SceneDestroy(scene);
		return false;
	}
	return true;
}

void world2SceneStep(World2Scene* scene, int stepIndex)
{
	const World2SceneInfo* info = world2SceneInfo(scene->id);
	if (scene->id == WORLD2_RAIN)
	{
		stepRain(scene, stepIndex);
	}
	else if (scene->id == WORLD2_SPINNER)
	{
		(void)cd2RevoluteJoint_GetAngle(scene->spinnerJoint); /* as Box2D's StepSpinner */
	}
	else if (scene->id == WORLD2_SIDE_SCROLLER)
	{
		stepSideScroller(scene, stepIndex);
	}
	cd2World_Step(scene->world, W2_TIME_STEP, info->subStepCount);
	if (scene->id == WORLD2_SIDE_SCROLLER)
	{
		countPickups(scene);
	}
}

bool world2SceneSnapshot(const World2Scene* scene, World2Snapshot* out)
{
	for (int i = 0; i < scene->bodyCount; ++i)
	{
		cd2BodyId id = scene->bodies[i];
		if (!cd2Body_IsValid(id))
		{
			continue;
		}
		cd2BodyType type = cd2Body_GetType(id);
		cd2Vec p = cd2Body_GetPosition(id), v = cd2Body_GetLinearVelocity(id);
		World2Body b;
		b.key = (uint64_t)(uint32_t)id.index1 | ((uint64_t)id.generation << 32);
		b.x = (double)p.x;
		b.y = (double)p.y;
		b.angle = (double)cd2RotGetAngle(cd2Body_GetRotation(id));
		b.vx = (double)v.x;
		b.vy = (double)v.y;
		b.w = (double)cd2Body_GetAngularVelocity(id);
		b.mass = (double)cd2Body_GetMass(id);
		b.type = type == CD_DYNAMIC_BODY ? WORLD2_DYNAMIC
										 : (type == CD_KINEMATIC_BODY ? WORLD2_KINEMATIC : WORLD2_STATIC);
		if (!world2SnapshotAdd(out, &b))
		{
			return false;
		}
	}
	return true;
}

static World2Quality sideScrollerQuality(const World2Scene* scene)
{
	World2Quality q;
	memset(&q, 0, sizeof(q));
	q.computed = true;
	cd2Vec p = cd2Body_GetPosition(scene->character);
	int once = 0;
	for (int i = 0; i < WORLD2_PICKUPS; ++i)
	{
		once += (scene->pickupBegin[i] == 1 && scene->pickupEnd[i] == 1) ? 1 : 0;
	}
	q.value = (double)p.x;
	q.limit = 69.0;
	q.pass = (double)p.x > q.limit && scene->lowestCharacterY > 0.5 && once == WORLD2_PICKUPS &&
			 scene->landedOnOneWay;
	snprintf(
		q.text, sizeof(q.text),
		"character at x = %.2f m, y = %.2f m (lowest %.2f); %d of %d pick-ups entered and left exactly once; "
		"%s the one-way platform",
		(double)p.x, (double)p.y, scene->lowestCharacterY, once, WORLD2_PICKUPS,
		scene->landedOnOneWay ? "landed on" : "never stood on");
	return q;
}

static World2Quality slingshotQuality(const World2Scene* scene, const World2Snapshot* start,
									  const World2Snapshot* end)
{
	World2Quality q;
	memset(&q, 0, sizeof(q));
	q.computed = true;
	/* Blocks of the towers (x 18.5-25.5 at the start) moved more than 0.5 m: toppled. */
	int toppled = 0, blocks = 0, below = 0;
	for (int i = 0; i < start->count; ++i)
	{
		const World2Body* b = &start->bodies[i];
		if (b->type != WORLD2_DYNAMIC || b->x < 18.5 || b->x > 25.5)
		{
			continue;
		}
		++blocks;
		for (int j = 0; j < end->count; ++j)
		{
			if (end->bodies[j].key == b->key)
			{
				double d = hypot(end->bodies[j].x - b->x, end->bodies[j].y - b->y);
				toppled += d > 0.5 ? 1 : 0;
				break;
			}
		}
	}
	for (int j = 0; j < end->count; ++j)
	{
		const World2Body* b = &end->bodies[j];
		below += (b->type == WORLD2_DYNAMIC && b->y < -0.5 && b->x > -10.0 && b->x < 400.0) ? 1 : 0;
	}
	double worstGap = 0.0;
	for (int i = 0; i < scene->bridgeJointCount; ++i)
	{
		cd2JointId joint = scene->bridgeJoints[i];
		if (!cd2Joint_IsValid(joint))
		{
			worstGap = 1e30;
			break;
		}
		cd2Vec a = cd2Body_GetWorldPoint(cd2Joint_GetBodyA(joint), scene->bridgeAnchorA[i]);
		cd2Vec b = cd2Body_GetWorldPoint(cd2Joint_GetBodyB(joint), scene->bridgeAnchorB[i]);
		double gap = hypot((double)(a.x - b.x), (double)(a.y - b.y));
		worstGap = gap > worstGap ? gap : worstGap;
	}
	q.value = (double)toppled;
	q.limit = 3.0;
	q.pass = toppled >= 3 && below == 0 && worstGap < 0.05;
	snprintf(q.text, sizeof(q.text),
			 "%d of %d tower blocks toppled; %d bodies below the ground; bridge joints' largest gap %.2f cm",
			 toppled, blocks, below, 100.0 * worstGap);
	return q;
}

World2Quality world2SceneQuality(const World2Scene* scene, const World2Snapshot* start,
								 const World2Snapshot* end, double time)
{
	if (scene->id == WORLD2_SIDE_SCROLLER)
	{
		return sideScrollerQuality(scene);
	}
	if (scene->id == WORLD2_SLINGSHOT)
	{
		return slingshotQuality(scene, start, end);
	}
	return world2CheckQuality(scene->id, start, end, time);
}

void world2SceneDestroy(World2Scene* scene)
{
	if (cd2World_IsValid(scene->world))
	{
		cd2DestroyWorld(scene->world);
	}
	free(scene->bodies);
	free(scene->rain);
	memset(scene, 0, sizeof(*scene));
}
