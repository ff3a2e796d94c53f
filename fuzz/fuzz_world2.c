/* libFuzzer target for the 2D world (world2.h): a byte string is a sequence of API calls (create
 * and destroy bodies, shapes, chains and joints; set velocities, transforms, types, sleep,
 * enabled; apply impulses; step; save and restore; calls with stale ids and with NaN, infinite or
 * absurd values). After every call the world's invariants are checked:
 *   world2-finite    every live body has a finite transform and velocity (for inputs within
 *                    +-1000 m and +-1000 m/s, the clamped values the sequence uses);
 *   world2-ids       every id the sequence holds as live is valid, every destroyed one stale, and
 *                    the world's body count equals the live ones;
 *   world2-refusal   a call with a bad value or a stale id is refused (the assert hook is called)
 *                    and a good one is not.
 * Leaks and memory errors are the sanitizers' part. */
#include "fuzz_decode.h"

enum
{
	WORLD_FUZZ_BODIES = 16,
	WORLD_FUZZ_JOINTS = 8,
	WORLD_FUZZ_OPS = 256
};

static int s_refusals;

static bool CountRefusal(const char* condition, const char* fileName, int lineNumber)
{
	(void)condition;
	(void)fileName;
	(void)lineNumber;
	++s_refusals;
	return false;
}

/* A lattice value clamped to +-limit (NaN and infinities become 0). */
static cdReal FuzzSane(FuzzReader* r, double limit)
{
	double v = (double)FuzzRawReal(r);
	if (!(v == v) || v > limit || v < -limit)
	{
		return v > limit ? (cdReal)limit : (v < -limit ? (cdReal)-limit : CD_R(0.0));
	}
	return (cdReal)v;
}

static cd2Vec FuzzSaneVec(FuzzReader* r, double limit)
{
	cdReal x = FuzzSane(r, limit);
	cdReal y = FuzzSane(r, limit);
	return cd2MakeVec(x, y);
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	FuzzReader r = FuzzBegin(data, size);
	cdSetAssertFcn(CountRefusal);
	cd2WorldDef wd = cd2DefaultWorldDef();
	wd.enableSleep = (FuzzByte(&r) & 1) != 0;
	cd2WorldId world = cd2CreateWorld(&wd);
	if (!cd2World_IsValid(world))
	{
		FuzzFail("world2-ids: the default world definition was refused");
	}
	cd2BodyId bodies[WORLD_FUZZ_BODIES];
	bool alive[WORLD_FUZZ_BODIES];
	cd2JointId joints[WORLD_FUZZ_JOINTS];
	memset(bodies, 0, sizeof(bodies));
	memset(alive, 0, sizeof(alive));
	memset(joints, 0, sizeof(joints));
	unsigned char* saved = NULL;
	size_t savedSize = 0;
	bool savedAlive[WORLD_FUZZ_BODIES];
	cd2BodyId savedBodies[WORLD_FUZZ_BODIES];
	cd2JointId savedJoints[WORLD_FUZZ_JOINTS];
	for (int op = 0; op < WORLD_FUZZ_OPS && r.at < r.size; ++op)
	{
		uint8_t kind = FuzzByte(&r) % 16;
		int i = FuzzByte(&r) % WORLD_FUZZ_BODIES;
		int before = s_refusals;
		int expected = 0;
		switch (kind)
		{
			case 0:
			case 1:
				if (!alive[i])
				{
					cd2BodyDef bd = cd2DefaultBodyDef();
					uint8_t t = FuzzByte(&r) % 3;
					bd.type = t == 0 ? CD_STATIC_BODY : (t == 1 ? CD_KINEMATIC_BODY : CD_DYNAMIC_BODY);
					bd.position = FuzzSaneVec(&r, 1000.0);
					bd.rotation = cd2MakeRot(FuzzSane(&r, 10.0));
					bd.linearVelocity = FuzzSaneVec(&r, 1000.0);
					bd.isBullet = (FuzzByte(&r) & 1) != 0;
					bodies[i] = cd2CreateBody(world, &bd);
					alive[i] = cd2Body_IsValid(bodies[i]);
					if (!alive[i])
					{
						FuzzFail("world2-refusal: a valid body definition was refused");
					}
				}
				else
				{
					cd2ShapeDef sd = cd2DefaultShapeDef();
					sd.isSensor = (FuzzByte(&r) & 7) == 0;
					sd.restitution = FuzzSane(&r, 1.0) < CD_R(0.0) ? CD_R(0.0) : CD_R(0.5);
					cd2Vec c = FuzzSaneVec(&r, 2.0);
					cdReal radius = cdAbs(FuzzSane(&r, 2.0)) + CD_R(0.05);
					switch (FuzzByte(&r) % 4)
					{
						case 0:
						{
							cd2Circle circle = {c, radius};
							cd2CreateCircleShape(bodies[i], &sd, &circle);
							break;
						}
						case 1:
						{
							cd2Capsule capsule = {c, cd2Add(c, FuzzSaneVec(&r, 2.0)), radius};
							cd2CreateCapsuleShape(bodies[i], &sd, &capsule);
							break;
						}
						case 2:
						{
							cd2Polygon polygon;
							cd2Box box = {c,
										  {radius, cdAbs(FuzzSane(&r, 2.0)) + CD_R(0.05)},
										  cd2MakeRot(FuzzSane(&r, 3.0))};
							if (cd2MakeBoxPolygon(box, &polygon) == CD_OK)
							{
								cd2CreatePolygonShape(bodies[i], &sd, &polygon);
							}
							break;
						}
						default:
						{
							cd2Segment segment = {c, cd2Add(c, FuzzSaneVec(&r, 2.0))};
							cd2CreateSegmentShape(bodies[i], &sd, &segment);
							break;
						}
					}
				}
				break;
			case 2:
				if (alive[i])
				{
					cd2DestroyBody(bodies[i]);
					alive[i] = false;
				}
				else if (bodies[i].index1 != 0)
				{
					cd2Body_ApplyLinearImpulseToCenter(bodies[i], cd2MakeVec(CD_R(1.0), CD_R(0.0)), true);
					expected = 1;
				}
				break;
			case 3:
			{
				int j = FuzzByte(&r) % WORLD_FUZZ_JOINTS;
				int b = FuzzByte(&r) % WORLD_FUZZ_BODIES;
				if (cd2Joint_IsValid(joints[j]))
				{
					cd2DestroyJoint(joints[j]);
				}
				else if (alive[i] && alive[b] && i != b)
				{
					switch (FuzzByte(&r) % 4)
					{
						case 0:
						{
							cd2RevoluteJointDef jd = cd2DefaultRevoluteJointDef();
							jd.bodyIdA = bodies[i];
							jd.bodyIdB = bodies[b];
							jd.localAnchorA = FuzzSaneVec(&r, 5.0);
							jd.enableLimit = true;
							jd.lowerAngle = -CD_R(1.0);
							jd.upperAngle = CD_R(1.0);
							jd.forceThreshold = CD_R(50.0); /* breaks on its joint event (step) */
							joints[j] = cd2CreateRevoluteJoint(world, &jd);
							break;
						}
						case 1:
						{
							cd2DistanceJointDef jd = cd2DefaultDistanceJointDef();
							jd.bodyIdA = bodies[i];
							jd.bodyIdB = bodies[b];
							jd.length = cdAbs(FuzzSane(&r, 10.0));
							joints[j] = cd2CreateDistanceJoint(world, &jd);
							break;
						}
						case 2:
						{
							cd2PrismaticJointDef jd = cd2DefaultPrismaticJointDef();
							jd.bodyIdA = bodies[i];
							jd.bodyIdB = bodies[b];
							jd.enableMotor = true;
							jd.maxMotorForce = CD_R(100.0);
							jd.motorSpeed = FuzzSane(&r, 10.0);
							joints[j] = cd2CreatePrismaticJoint(world, &jd);
							break;
						}
						default:
						{
							cd2WeldJointDef jd = cd2DefaultWeldJointDef();
							jd.bodyIdA = bodies[i];
							jd.bodyIdB = bodies[b];
							joints[j] = cd2CreateWeldJoint(world, &jd);
							break;
						}
					}
					if (!cd2Joint_IsValid(joints[j]))
					{
						FuzzFail("world2-refusal: a valid joint definition was refused");
					}
				}
				break;
			}
			case 4:
				if (alive[i])
				{
					cdReal v = FuzzRawReal(&r);
					bool bad = !cdIsValidReal(v);
					cd2Body_SetLinearVelocity(bodies[i], cd2MakeVec(v, CD_R(0.0)));
					expected = bad ? 1 : 0;
					if (!bad && cdAbs(v) > CD_R(1000.0))
					{
						cd2Body_SetLinearVelocity(bodies[i], CD2_VEC_ZERO); /* keep the sane range */
					}
				}
				break;
			case 5:
				if (alive[i])
				{
					cd2Body_SetTransform(bodies[i], FuzzSaneVec(&r, 1000.0), cd2MakeRot(FuzzSane(&r, 10.0)));
				}
				break;
			case 6:
				if (alive[i])
				{
					uint8_t t = FuzzByte(&r) % 3;
					cd2Body_SetType(bodies[i],
									t == 0 ? CD_STATIC_BODY : (t == 1 ? CD_KINEMATIC_BODY : CD_DYNAMIC_BODY));
				}
				break;
			case 7:
				if (alive[i])
				{
					if (cd2Body_IsEnabled(bodies[i]))
					{
						cd2Body_Disable(bodies[i]);
					}
					else
					{
						cd2Body_Enable(bodies[i]);
					}
				}
				break;
			case 8:
				if (alive[i])
				{
					cd2Body_SetAwake(bodies[i], (FuzzByte(&r) & 1) != 0);
				}
				break;
			case 9:
				if (alive[i])
				{
					cd2Body_ApplyLinearImpulse(bodies[i], FuzzSaneVec(&r, 100.0), FuzzSaneVec(&r, 1000.0),
											   true);
				}
				break;
			case 10:
			{
				/* Bad definitions never enter the world. */
				cd2BodyDef bd = cd2DefaultBodyDef();
				bd.position = cd2MakeVec(FuzzRawReal(&r), FuzzRawReal(&r));
				bd.angularVelocity = FuzzRawReal(&r);
				bool bad = !cd2IsValidVec(bd.position) || !cdIsValidReal(bd.angularVelocity);
				cd2BodyId id = cd2CreateBody(world, &bd);
				if (bad != (id.index1 == 0))
				{
					FuzzFail("world2-refusal: a body definition with bad=%d got index %d", (int)bad,
							 (int)id.index1);
				}
				expected = bad ? 1 : 0;
				if (!bad)
				{
					cd2DestroyBody(id);
				}
				break;
			}
			case 11:
				if (saved == NULL)
				{
					savedSize = cd2World_GetStateSize(world);
					saved = (unsigned char*)malloc(savedSize);
					if (saved == NULL || cd2World_SaveState(world, saved, savedSize) != CD_OK)
					{
						FuzzFail("world2-ids: save failed");
					}
					memcpy(savedAlive, alive, sizeof(alive));
					memcpy(savedBodies, bodies, sizeof(bodies));
					memcpy(savedJoints, joints, sizeof(joints));
				}
				else
				{
					if (cd2World_RestoreState(world, saved, savedSize) != CD_OK)
					{
						FuzzFail("world2-ids: restore failed");
					}
					memcpy(alive, savedAlive, sizeof(alive));
					memcpy(bodies, savedBodies, sizeof(bodies));
					memcpy(joints, savedJoints, sizeof(joints));
					free(saved);
					saved = NULL;
				}
				break;
			default:
			{
				cd2World_Step(world, CD_R(1.0) / CD_R(60.0), 1 + FuzzByte(&r) % 4);
				/* Joint events name live joints over their threshold, with finite reactions; the
				 * joint breaks (is destroyed) on its event. */
				cd2JointEvents je = cd2World_GetJointEvents(world);
				for (int e = 0; e < je.count; ++e)
				{
					const cd2JointEvent* event = je.jointEvents + e;
					cdReal force = cd2Length(event->force);
					if (!cd2Joint_IsValid(event->jointId) || !cdIsValidReal(force) ||
						!cdIsValidReal(event->torque) ||
						!(force > cd2Joint_GetForceThreshold(event->jointId)))
					{
						FuzzFail("world2-events: joint event %d of %d: stale or not over the threshold", e,
								 je.count);
					}
					cd2DestroyJoint(event->jointId);
				}
				break;
			}
		}
		if (s_refusals - before != expected)
		{
			FuzzFail("world2-refusal: op %d kind %d: %d refusals, expected %d", op, (int)kind,
					 s_refusals - before, expected);
		}
		int live = 0;
		for (int k = 0; k < WORLD_FUZZ_BODIES; ++k)
		{
			if (alive[k])
			{
				live += 1;
				if (!cd2Body_IsValid(bodies[k]))
				{
					FuzzFail("world2-ids: op %d: live body %d is not valid", op, k);
				}
				cd2Transform xf = cd2Body_GetTransform(bodies[k]);
				if (!cd2IsValidVec(xf.p) || !cd2IsValidRot(xf.q) ||
					!cd2IsValidVec(cd2Body_GetLinearVelocity(bodies[k])) ||
					!cdIsValidReal(cd2Body_GetAngularVelocity(bodies[k])))
				{
					FuzzFail("world2-finite: op %d: body %d at (%g, %g)", op, k, (double)xf.p.x,
							 (double)xf.p.y);
				}
			}
			else if (bodies[k].index1 != 0 && cd2Body_IsValid(bodies[k]))
			{
				FuzzFail("world2-ids: op %d: destroyed body %d is still valid", op, k);
			}
		}
		if (cd2World_GetCounters(world).bodyCount != live)
		{
			FuzzFail("world2-ids: op %d: %d bodies in the world, %d live", op,
					 cd2World_GetCounters(world).bodyCount, live);
		}
	}
	free(saved);
	cd2DestroyWorld(world);
	cdSetAssertFcn(NULL);
	return 0;
}
