/* A falling box: the smallest 2D world (see docs/DYNAMICS.md). Prints where the box comes to
 * rest on the ground and exits with 1 if it did not. */
#include <collide/collide.h>
#include <stdio.h>

int main(void)
{
	cd2WorldDef worldDef = cd2DefaultWorldDef(); /* gravity (0, -10) */
	cd2WorldId world = cd2CreateWorld(&worldDef);

	cd2BodyDef groundDef = cd2DefaultBodyDef(); /* static */
	groundDef.position = cd2MakeVec(0.0f, -1.0f);
	cd2BodyId ground = cd2CreateBody(world, &groundDef);
	cd2ShapeDef shapeDef = cd2DefaultShapeDef();
	cd2Polygon groundBox;
	cd2MakeBoxPolygon((cd2Box){{0.0f, 0.0f}, {50.0f, 1.0f}, {1.0f, 0.0f}}, &groundBox);
	cd2CreatePolygonShape(ground, &shapeDef, &groundBox);

	cd2BodyDef boxDef = cd2DefaultBodyDef();
	boxDef.type = CD_DYNAMIC_BODY;
	boxDef.position = cd2MakeVec(0.0f, 4.0f);
	boxDef.rotation = cd2MakeRot(0.3f);
	cd2BodyId box = cd2CreateBody(world, &boxDef);
	cd2Polygon boxShape;
	cd2MakeBoxPolygon((cd2Box){{0.0f, 0.0f}, {0.5f, 0.5f}, {1.0f, 0.0f}}, &boxShape);
	cd2CreatePolygonShape(box, &shapeDef, &boxShape);

	for (int i = 0; i < 120; ++i) /* two seconds at 60 Hz, 4 sub-steps */
	{
		cd2World_Step(world, 1.0f / 60.0f, 4);
	}
	cd2Vec p = cd2Body_GetPosition(box);
	printf("box at (%.3f, %.3f), angle %.3f, %s\n", (double)p.x, (double)p.y,
		   (double)cd2RotGetAngle(cd2Body_GetRotation(box)), cd2Body_IsAwake(box) ? "awake" : "asleep");
	cd2DestroyWorld(world);
	return (p.y > 0.45f && p.y < 0.55f) ? 0 : 1;
}
