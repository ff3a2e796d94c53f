/* collide: the wide contact solver. The coloured contact constraints (graph_color.h: no two of a
 * colour share a movable body) are packed CD_W to a block, colour by colour, and solved a block at a
 * time with the helpers of wide2.h: the same arithmetic as the one-by-one solver of
 * contact_solver2.c, lane by lane, so a colour's result does not depend on how it is cut into
 * blocks, and the SIMD and scalar versions of the helpers give the same bits. Immovable bodies
 * (static, asleep) point at the zero body after the awake ones, whose velocity stays zero. The
 * overflow colour stays with the one-by-one solver, after the blocks. */
#include "world2_internal.h"

#include "../base/graph_color.h"

#include <string.h>

/* Forced inlining: the solve's two passes, and the prefetch helper (gcc counts a function that only
 * prefetches as pure and drops its calls unless it is inlined first). */
#if defined(__GNUC__) || defined(__clang__)
#define CD2_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define CD2_ALWAYS_INLINE inline
#endif

/* The gather below reads a solver body as nine consecutive reals. */
typedef char cd2SolverBodyIsPacked[sizeof(cd2SolverBody) == 9 * sizeof(cdReal) ? 1 : -1];

typedef struct cd2BodyLanes
{
	cdW vx, vy, w, dpx, dpy, qc, qs;
} cd2BodyLanes;

static inline cd2BodyLanes cd2GatherBodies(const cd2SolverBody* bodies, const int* index)
{
	cd2BodyLanes out;
#if CD_WIDE_AVX2
	/* Rows of four reals: body i in the low half, body i + 4 in the high half, then the four-by-four
	 * transpose of SSE2 in each half (column k: real k of bodies 0..3 | of bodies 4..7). */
	const float* b[8];
	for (int i = 0; i < 8; ++i)
	{
		b[i] = (const float*)(bodies + index[i]);
	}
	for (int half = 0; half < 2; ++half)
	{
		int o = 4 * half;
		__m256 r0 = _mm256_set_m128(_mm_loadu_ps(b[4] + o), _mm_loadu_ps(b[0] + o));
		__m256 r1 = _mm256_set_m128(_mm_loadu_ps(b[5] + o), _mm_loadu_ps(b[1] + o));
		__m256 r2 = _mm256_set_m128(_mm_loadu_ps(b[6] + o), _mm_loadu_ps(b[2] + o));
		__m256 r3 = _mm256_set_m128(_mm_loadu_ps(b[7] + o), _mm_loadu_ps(b[3] + o));
		__m256 t0 = _mm256_unpacklo_ps(r0, r1), t1 = _mm256_unpackhi_ps(r0, r1);
		__m256 t2 = _mm256_unpacklo_ps(r2, r3), t3 = _mm256_unpackhi_ps(r2, r3);
		__m256 c0 = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0));
		__m256 c1 = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2));
		__m256 c2 = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0));
		__m256 c3 = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(3, 2, 3, 2));
		if (half == 0)
		{
			out.vx = c0;
			out.vy = c1;
			out.w = c2;
			out.dpx = c3;
		}
		else
		{
			out.dpy = c0;
			out.qc = c1;
			out.qs = c2;
		}
	}
#elif CD_WIDE_NEON
	const float* b0 = (const float*)(bodies + index[0]);
	const float* b1 = (const float*)(bodies + index[1]);
	const float* b2 = (const float*)(bodies + index[2]);
	const float* b3 = (const float*)(bodies + index[3]);
	for (int half = 0; half < 2; ++half)
	{
		/* Rows r0..r3 are reals 4 * half .. 4 * half + 3 of the four bodies; transposed, column k
		 * holds real 4 * half + k of every lane. */
		float32x4_t r0 = vld1q_f32(b0 + 4 * half), r1 = vld1q_f32(b1 + 4 * half);
		float32x4_t r2 = vld1q_f32(b2 + 4 * half), r3 = vld1q_f32(b3 + 4 * half);
		float32x4_t t0 = vzip1q_f32(r0, r1), t1 = vzip2q_f32(r0, r1);
		float32x4_t t2 = vzip1q_f32(r2, r3), t3 = vzip2q_f32(r2, r3);
		float32x4_t c0 =
			vreinterpretq_f32_f64(vzip1q_f64(vreinterpretq_f64_f32(t0), vreinterpretq_f64_f32(t2)));
		float32x4_t c1 =
			vreinterpretq_f32_f64(vzip2q_f64(vreinterpretq_f64_f32(t0), vreinterpretq_f64_f32(t2)));
		float32x4_t c2 =
			vreinterpretq_f32_f64(vzip1q_f64(vreinterpretq_f64_f32(t1), vreinterpretq_f64_f32(t3)));
		float32x4_t c3 =
			vreinterpretq_f32_f64(vzip2q_f64(vreinterpretq_f64_f32(t1), vreinterpretq_f64_f32(t3)));
		if (half == 0)
		{
			out.vx = c0;
			out.vy = c1;
			out.w = c2;
			out.dpx = c3;
		}
		else
		{
			out.dpy = c0;
			out.qc = c1;
			out.qs = c2;
		}
	}
#elif CD_WIDE_SSE
	const float* b0 = (const float*)(bodies + index[0]);
	const float* b1 = (const float*)(bodies + index[1]);
	const float* b2 = (const float*)(bodies + index[2]);
	const float* b3 = (const float*)(bodies + index[3]);
	__m128 r0 = _mm_loadu_ps(b0), r1 = _mm_loadu_ps(b1), r2 = _mm_loadu_ps(b2), r3 = _mm_loadu_ps(b3);
	_MM_TRANSPOSE4_PS(r0, r1, r2, r3);
	out.vx = r0;
	out.vy = r1;
	out.w = r2;
	out.dpx = r3;
	__m128 s0 = _mm_loadu_ps(b0 + 4), s1 = _mm_loadu_ps(b1 + 4), s2 = _mm_loadu_ps(b2 + 4),
		   s3 = _mm_loadu_ps(b3 + 4);
	_MM_TRANSPOSE4_PS(s0, s1, s2, s3);
	out.dpy = s0;
	out.qc = s1;
	out.qs = s2;
#elif defined(CD_WIDE_WASM)
	const float* b0 = (const float*)(bodies + index[0]);
	const float* b1 = (const float*)(bodies + index[1]);
	const float* b2 = (const float*)(bodies + index[2]);
	const float* b3 = (const float*)(bodies + index[3]);
	for (int half = 0; half < 2; ++half)
	{
		/* Rows r0..r3 are reals 4 * half .. 4 * half + 3 of the four bodies; transposed, column k
		 * holds real 4 * half + k of every lane. */
		v128_t r0 = wasm_v128_load(b0 + 4 * half), r1 = wasm_v128_load(b1 + 4 * half);
		v128_t r2 = wasm_v128_load(b2 + 4 * half), r3 = wasm_v128_load(b3 + 4 * half);
		v128_t t0 = wasm_i32x4_shuffle(r0, r1, 0, 4, 1, 5), t1 = wasm_i32x4_shuffle(r2, r3, 0, 4, 1, 5);
		v128_t t2 = wasm_i32x4_shuffle(r0, r1, 2, 6, 3, 7), t3 = wasm_i32x4_shuffle(r2, r3, 2, 6, 3, 7);
		v128_t c0 = wasm_i32x4_shuffle(t0, t1, 0, 1, 4, 5), c1 = wasm_i32x4_shuffle(t0, t1, 2, 3, 6, 7);
		v128_t c2 = wasm_i32x4_shuffle(t2, t3, 0, 1, 4, 5), c3 = wasm_i32x4_shuffle(t2, t3, 2, 3, 6, 7);
		if (half == 0)
		{
			out.vx = c0;
			out.vy = c1;
			out.w = c2;
			out.dpx = c3;
		}
		else
		{
			out.dpy = c0;
			out.qc = c1;
			out.qs = c2;
		}
	}
#else
	for (int i = 0; i < CD_W; ++i)
	{
		const cd2SolverBody* b = bodies + index[i];
		out.vx.v[i] = b->linearVelocity.x;
		out.vy.v[i] = b->linearVelocity.y;
		out.w.v[i] = b->angularVelocity;
		out.dpx.v[i] = b->deltaPosition.x;
		out.dpy.v[i] = b->deltaPosition.y;
		out.qc.v[i] = b->deltaRotation.c;
		out.qs.v[i] = b->deltaRotation.s;
	}
#endif
	return out;
}

/* Writes the velocities of the movable lanes back (the zero body and kinematic bodies are shared by
 * blocks of one colour, which may run on different threads: they are only read). */
static inline void cd2ScatterVelocities(cd2SolverBody* bodies, const int* index, const unsigned char* moves,
										cdW vx, cdW vy, cdW w, cdW dpx)
{
#if CD_WIDE_AVX2
	/* Back to rows (vx, vy, w, dpx) in each half: row k holds body k in its low half and body k + 4
	 * in its high half (dpx as gathered, unchanged). */
	__m256 t0 = _mm256_unpacklo_ps(vx, vy), t1 = _mm256_unpackhi_ps(vx, vy);
	__m256 t2 = _mm256_unpacklo_ps(w, dpx), t3 = _mm256_unpackhi_ps(w, dpx);
	__m256 rows[4];
	rows[0] = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0));
	rows[1] = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2));
	rows[2] = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0));
	rows[3] = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(3, 2, 3, 2));
	for (int k = 0; k < 4; ++k)
	{
		if (moves[k] != 0)
		{
			_mm_storeu_ps((float*)(bodies + index[k]), _mm256_castps256_ps128(rows[k]));
		}
		if (moves[k + 4] != 0)
		{
			_mm_storeu_ps((float*)(bodies + index[k + 4]), _mm256_extractf128_ps(rows[k], 1));
		}
	}
#elif CD_WIDE_NEON
	/* Back to rows (vx, vy, w, dpx) of each body, one store each (dpx as gathered, unchanged). */
	float32x4_t t0 = vzip1q_f32(vx, vy), t1 = vzip2q_f32(vx, vy);
	float32x4_t t2 = vzip1q_f32(w, dpx), t3 = vzip2q_f32(w, dpx);
	float32x4_t rows[4];
	rows[0] = vreinterpretq_f32_f64(vzip1q_f64(vreinterpretq_f64_f32(t0), vreinterpretq_f64_f32(t2)));
	rows[1] = vreinterpretq_f32_f64(vzip2q_f64(vreinterpretq_f64_f32(t0), vreinterpretq_f64_f32(t2)));
	rows[2] = vreinterpretq_f32_f64(vzip1q_f64(vreinterpretq_f64_f32(t1), vreinterpretq_f64_f32(t3)));
	rows[3] = vreinterpretq_f32_f64(vzip2q_f64(vreinterpretq_f64_f32(t1), vreinterpretq_f64_f32(t3)));
	for (int k = 0; k < 4; ++k)
	{
		if (moves[k] != 0)
		{
			vst1q_f32((float*)(bodies + index[k]), rows[k]);
		}
	}
#elif CD_WIDE_SSE
	/* Back to rows (vx, vy, w, dpx) of each body, one store each (dpx as gathered, unchanged). */
	_MM_TRANSPOSE4_PS(vx, vy, w, dpx);
	if (moves[0] != 0)
	{
		_mm_storeu_ps((float*)(bodies + index[0]), vx);
	}
	if (moves[1] != 0)
	{
		_mm_storeu_ps((float*)(bodies + index[1]), vy);
	}
	if (moves[2] != 0)
	{
		_mm_storeu_ps((float*)(bodies + index[2]), w);
	}
	if (moves[3] != 0)
	{
		_mm_storeu_ps((float*)(bodies + index[3]), dpx);
	}
#else
	(void)dpx;
	cdReal x[CD_W], y[CD_W], a[CD_W];
	cdWStore(x, vx);
	cdWStore(y, vy);
	cdWStore(a, w);
	for (int i = 0; i < CD_W; ++i)
	{
		if (moves[i] == 0)
		{
			continue;
		}
		cd2SolverBody* b = bodies + index[i];
		b->linearVelocity.x = x[i];
		b->linearVelocity.y = y[i];
		b->angularVelocity = a[i];
	}
#endif
}

bool cd2PrepareContactsWide(cd2World* world, cd2StepContext* context)
{
	int n = context->constraintCount;
	const int* color = context->colorOfConstraint;
	context->wideCount = 0;
	context->overflowStart = 0;
	context->colorCount = 0;
	if (color == NULL || n == 0)
	{
		return true;
	}
	int overflowStart = n;
	int blockCount = 0;
	int colorCount = 0;
	for (int i = 0; i < n;)
	{
		if (color[i] >= CD_GRAPH_COLOR_COUNT)
		{
			overflowStart = i;
			break;
		}
		int j = i;
		while (j < n && color[j] == color[i])
		{
			++j;
		}
		context->colorBlockStart[colorCount] = blockCount;
		context->colorConstraintStart[colorCount] = i;
		++colorCount;
		blockCount += (j - i + CD_W - 1) / CD_W;
		i = j;
	}
	context->colorBlockStart[colorCount] = blockCount;
	context->colorConstraintStart[colorCount] = overflowStart;
	cd2ContactConstraintWide* wide = (cd2ContactConstraintWide*)cdArena_AllocUncleared(
		&world->arena, (size_t)blockCount * sizeof(cd2ContactConstraintWide));
	if (blockCount > 0 && wide == NULL)
	{
		return false;
	}
	context->colorCount = colorCount;
	context->wide = wide;
	context->wideCount = blockCount;
	context->overflowStart = overflowStart;
	return true;
}

/* How many constraints ahead the pack asks for the contact records: they are read in colour order,
 * scattered over the contact array. */
#define CD2_PACK_PREFETCH_AHEAD 24

/* Asks for the lines of contact record `contact` from its normal to its points: what
 * cd2PrepareContactConstraint reads and the store writes. */
static CD2_ALWAYS_INLINE void cd2PrefetchContactRecord(const cd2World* world, int contact)
{
#if defined(__GNUC__) || defined(__clang__)
	const char* first = (const char*)&world->contacts.data[contact].normal;
	const char* last = (const char*)world->contacts.data[contact].cache;
	for (const char* p = first; p < last; p += 64)
	{
		__builtin_prefetch(p);
	}
	__builtin_prefetch(last - 1);
#else
	(void)world;
	(void)contact;
#endif
}

/* The same for writing: the lines of the record's rolling impulse and points, and of the points'
 * approach speeds. */
static CD2_ALWAYS_INLINE void cd2PrefetchContactForStore(const cd2World* world, int contact, bool approach)
{
#if defined(__GNUC__) || defined(__clang__)
	const cd2Contact* record = world->contacts.data + contact;
	const char* first = (const char*)&record->rollingImpulse;
	const char* last = (const char*)record->cache;
	for (const char* p = first; p < last; p += 64)
	{
		__builtin_prefetch(p, 1);
	}
	__builtin_prefetch(last - 1, 1);
	if (approach)
	{
		__builtin_prefetch(&record->cache[0].relativeVelocity, 1);
		__builtin_prefetch(&record->cache[1].relativeVelocity, 1);
	}
#else
	(void)world;
	(void)contact;
	(void)approach;
#endif
}

static CD2_ALWAYS_INLINE void cd2PrefetchContact(const cd2World* world, const cd2StepContext* context, int i)
{
	if (i < context->constraintCount)
	{
		cd2PrefetchContactRecord(world, context->pairs[i].contact);
	}
}

/* How many blocks ahead the pack asks for the lines it writes. */
#define CD2_PACK_STORE_AHEAD 2

/* What the pack reads of a block's contacts and bodies, lane by lane (zero in empty lanes and for a
 * missing second point), before the wide arithmetic. */
typedef struct cd2PackInput
{
	cdReal invMassA[CD_W], invIA[CD_W], invMassB[CD_W], invIB[CD_W];
	cdReal normalX[CD_W], normalY[CD_W];
	cdReal vAx[CD_W], vAy[CD_W], wA[CD_W], vBx[CD_W], vBy[CD_W], wB[CD_W];
	cdReal pointCount[CD_W];
	cdReal anchorAx[2][CD_W], anchorAy[2][CD_W], anchorBx[2][CD_W], anchorBy[2][CD_W];
	cdReal separation[2][CD_W];
} cd2PackInput;

/* cd2PrepareContactConstraint for the CD_W lanes of a block: the contact's own values are copied lane
 * by lane, and the derived ones (masses, base separations, approach speeds) computed with the same
 * operations in the same order on whole blocks, so every lane gets the one-by-one bits. */
bool cd2PackContactsWide(const cd2World* world, cd2StepContext* context, int startBlock, int endBlock)
{
	bool anyBounces = false;
	static const cd2SolverBody zeroBody = {{CD_R(0.0), CD_R(0.0)}, CD_R(0.0), {CD_R(0.0), CD_R(0.0)},
										   {CD_R(1.0), CD_R(0.0)}, CD_R(0.0), CD_R(0.0)};
	int zeroIndex = context->bodyCount;
	bool warm = context->enableWarmStarting;
	cdW zero = cdWZero(), one = cdWSplat(CD_R(1.0));
	int color = 0;
	for (int block = startBlock; block < endBlock; ++block)
	{
		while (context->colorBlockStart[color + 1] <= block)
		{
			++color;
		}
		/* The colour's constraints [first, last), CD_W to a block. */
		int first = context->colorConstraintStart[color] + CD_W * (block - context->colorBlockStart[color]);
		int last = context->colorConstraintStart[color + 1];
		if (block == startBlock)
		{
			for (int i = first; i < first + CD2_PACK_PREFETCH_AHEAD; ++i)
			{
				cd2PrefetchContact(world, context, i);
			}
		}
		cd2ContactConstraintWide* w = context->wide + block;
#if defined(__GNUC__) || defined(__clang__)
		/* The lines of a block a few ahead, for writing (past this range too: with one worker the next
		 * range follows). Asking early makes the many lines a block writes arrive together; waiting
		 * for each at its first store was a third of the pack's time. */
		if (block + CD2_PACK_STORE_AHEAD < context->wideCount)
		{
			const char* next = (const char*)(w + CD2_PACK_STORE_AHEAD);
			for (size_t o = 0; o < sizeof(cd2ContactConstraintWide); o += 64)
			{
				__builtin_prefetch(next + o, 1);
			}
			__builtin_prefetch(next + sizeof(cd2ContactConstraintWide) - 1, 1);
		}
#endif
		cd2PackInput in;
		memset(&in, 0, sizeof(in));
		cdReal restitution[CD_W] = {0}, friction[CD_W] = {0}, tangentSpeed[CD_W] = {0};
		cdReal rollingResistance[CD_W] = {0}, rollingImpulse[CD_W] = {0};
		cdReal biasRate[CD_W] = {0}, massScale[CD_W] = {0}, impulseScale[CD_W] = {0};
		cdReal normalImpulse[2][CD_W] = {{0}}, tangentImpulse[2][CD_W] = {{0}};
		bool bounces = false;
		for (int lane = 0; lane < CD_W; ++lane)
		{
			w->indexA[lane] = zeroIndex;
			w->indexB[lane] = zeroIndex;
			w->contact[lane] = -1;
			w->pointCount[lane] = 0;
			w->movesA[lane] = 0;
			w->movesB[lane] = 0;
			/* An empty lane's rotation is the identity, like the zero body's. */
			if (first + lane >= last)
			{
				continue;
			}
			/* The next blocks' records (of this colour or the next). */
			cd2PrefetchContact(world, context, first + lane + CD2_PACK_PREFETCH_AHEAD);
			const cd2ConstraintPair* pair = context->pairs + first + lane;
			const cd2Contact* contact = world->contacts.data + pair->contact;
			/* A sleeping or static body is immovable for this step. */
			const cd2SolverBody* bodyA = pair->indexA < 0 ? &zeroBody : context->bodies + pair->indexA;
			const cd2SolverBody* bodyB = pair->indexB < 0 ? &zeroBody : context->bodies + pair->indexB;
			cdReal mA = bodyA->invMass, iA = bodyA->invInertia, mB = bodyB->invMass, iB = bodyB->invInertia;
			w->contact[lane] = pair->contact;
			w->pointCount[lane] = (unsigned char)contact->pointCount;
			w->indexA[lane] = pair->indexA < 0 ? zeroIndex : pair->indexA;
			w->indexB[lane] = pair->indexB < 0 ? zeroIndex : pair->indexB;
			/* Immovable: both inverse masses zero (the velocity update would add nothing). */
			w->movesA[lane] = (unsigned char)(pair->indexA >= 0 && (mA != CD_R(0.0) || iA != CD_R(0.0)));
			w->movesB[lane] = (unsigned char)(pair->indexB >= 0 && (mB != CD_R(0.0) || iB != CD_R(0.0)));
			const cd2Softness* soft =
				(mA == CD_R(0.0) || mB == CD_R(0.0)) ? &context->staticSoftness : &context->contactSoftness;
			biasRate[lane] = soft->biasRate;
			massScale[lane] = soft->massScale;
			impulseScale[lane] = soft->impulseScale;
			in.invMassA[lane] = mA;
			in.invIA[lane] = iA;
			in.invMassB[lane] = mB;
			in.invIB[lane] = iB;
			cd2Vec n = contact->normal;
			in.normalX[lane] = n.x;
			in.normalY[lane] = n.y;
			friction[lane] = contact->friction;
			restitution[lane] = contact->restitution;
			bounces = bounces || contact->restitution != CD_R(0.0);
			rollingResistance[lane] = contact->rollingResistance;
			tangentSpeed[lane] = contact->tangentSpeed;
			rollingImpulse[lane] = contact->rollingImpulse;
			in.vAx[lane] = bodyA->linearVelocity.x;
			in.vAy[lane] = bodyA->linearVelocity.y;
			in.wA[lane] = bodyA->angularVelocity;
			in.vBx[lane] = bodyB->linearVelocity.x;
			in.vBy[lane] = bodyB->linearVelocity.y;
			in.wB[lane] = bodyB->angularVelocity;
			in.pointCount[lane] = (cdReal)contact->pointCount;
			for (int k = 0; k < contact->pointCount; ++k)
			{
				const cd2ContactPoint* mp = contact->points + k;
				in.anchorAx[k][lane] = mp->anchorA.x;
				in.anchorAy[k][lane] = mp->anchorA.y;
				in.anchorBx[k][lane] = mp->anchorB.x;
				in.anchorBy[k][lane] = mp->anchorB.y;
				in.separation[k][lane] = mp->separation;
				normalImpulse[k][lane] = warm ? mp->normalImpulse : CD_R(0.0);
				tangentImpulse[k][lane] = warm ? mp->tangentImpulse : CD_R(0.0);
			}
		}
		w->bounces = bounces;
		anyBounces = anyBounces || bounces;
		cdW mA = cdWLoad(in.invMassA), iA = cdWLoad(in.invIA), mB = cdWLoad(in.invMassB),
			iB = cdWLoad(in.invIB);
		cdW nx = cdWLoad(in.normalX), ny = cdWLoad(in.normalY);
		cdW tx = ny, ty = cdWNeg(nx);
		cdW vAx = cdWLoad(in.vAx), vAy = cdWLoad(in.vAy), wA = cdWLoad(in.wA);
		cdW vBx = cdWLoad(in.vBx), vBy = cdWLoad(in.vBy), wB = cdWLoad(in.wB);
		w->invMassA = mA;
		w->invIA = iA;
		w->invMassB = mB;
		w->invIB = iB;
		w->normalX = nx;
		w->normalY = ny;
		w->friction = cdWLoad(friction);
		w->tangentSpeed = cdWLoad(tangentSpeed);
		w->rollingResistance = cdWLoad(rollingResistance);
		w->rollingImpulse = cdWLoad(rollingImpulse);
		w->biasRate = cdWLoad(biasRate);
		w->massScale = cdWLoad(massScale);
		w->impulseScale = cdWLoad(impulseScale);
		w->restitution = cdWLoad(restitution);
		cdW iSum = cdWAdd(iA, iB);
		cdW positive = cdWGreater(iSum, zero);
		w->rollingMass = cdWSelect(positive, cdWDiv(one, cdWSelect(positive, iSum, one)), zero);
		cdW mSum = cdWAdd(mA, mB);
		cdW pointCount = cdWLoad(in.pointCount);
		for (int k = 0; k < 2; ++k)
		{
			cd2ContactPointWide* wp = w->points + k;
			/* Lanes without this point keep zeros, as one by one. */
			cdW has = cdWGreater(pointCount, cdWSplat((cdReal)k));
			cdW aAx = cdWLoad(in.anchorAx[k]), aAy = cdWLoad(in.anchorAy[k]);
			cdW aBx = cdWLoad(in.anchorBx[k]), aBy = cdWLoad(in.anchorBy[k]);
			wp->anchorAx = aAx;
			wp->anchorAy = aAy;
			wp->anchorBx = aBx;
			wp->anchorBy = aBy;
			wp->baseSeparation =
				cdWSelect(has,
						  cdWSub(cdWLoad(in.separation[k]),
								 cdWAdd(cdWMul(cdWSub(aBx, aAx), nx), cdWMul(cdWSub(aBy, aAy), ny))),
						  zero);
			wp->normalImpulse = cdWLoad(normalImpulse[k]);
			wp->tangentImpulse = cdWLoad(tangentImpulse[k]);
			wp->maxNormalImpulse = zero;
			cdW rnA = cdWSub(cdWMul(aAx, ny), cdWMul(aAy, nx));
			cdW rnB = cdWSub(cdWMul(aBx, ny), cdWMul(aBy, nx));
			cdW kNormal = cdWAdd(cdWAdd(mSum, cdWMul(cdWMul(iA, rnA), rnA)), cdWMul(cdWMul(iB, rnB), rnB));
			cdW usable = cdWAnd(has, cdWGreater(kNormal, zero));
			wp->normalMass = cdWSelect(usable, cdWDiv(one, cdWSelect(usable, kNormal, one)), zero);
			cdW rtA = cdWSub(cdWMul(aAx, ty), cdWMul(aAy, tx));
			cdW rtB = cdWSub(cdWMul(aBx, ty), cdWMul(aBy, tx));
			cdW kTangent = cdWAdd(cdWAdd(mSum, cdWMul(cdWMul(iA, rtA), rtA)), cdWMul(cdWMul(iB, rtB), rtB));
			usable = cdWAnd(has, cdWGreater(kTangent, zero));
			wp->tangentMass = cdWSelect(usable, cdWDiv(one, cdWSelect(usable, kTangent, one)), zero);
			/* The approach speed at the start of the step. */
			cdW vrAx = cdWAdd(vAx, cdWMul(cdWNeg(wA), aAy)), vrAy = cdWAdd(vAy, cdWMul(wA, aAx));
			cdW vrBx = cdWAdd(vBx, cdWMul(cdWNeg(wB), aBy)), vrBy = cdWAdd(vBy, cdWMul(wB, aBx));
			wp->relativeVelocity =
				cdWSelect(has, cdWAdd(cdWMul(nx, cdWSub(vrBx, vrAx)), cdWMul(ny, cdWSub(vrBy, vrAy))), zero);
		}
	}
	return anyBounces;
}

void cd2WarmStartContactsWide(cd2StepContext* context, int start, int end)
{
	cd2SolverBody* bodies = context->bodies;
	for (int i = start; i < end; ++i)
	{
		cd2ContactConstraintWide* c = context->wide + i;
		cd2BodyLanes a = cd2GatherBodies(bodies, c->indexA);
		cd2BodyLanes b = cd2GatherBodies(bodies, c->indexB);
		cdW nx = c->normalX, ny = c->normalY;
		cdW tx = ny, ty = cdWNeg(nx);
		cdW vAx = a.vx, vAy = a.vy, wA = a.w, vBx = b.vx, vBy = b.vy, wB = b.w;
		for (int k = 0; k < 2; ++k)
		{
			const cd2ContactPointWide* cp = c->points + k;
			cdW Px = cdWAdd(cdWMul(cp->normalImpulse, nx), cdWMul(cp->tangentImpulse, tx));
			cdW Py = cdWAdd(cdWMul(cp->normalImpulse, ny), cdWMul(cp->tangentImpulse, ty));
			cdW crossA = cdWSub(cdWMul(cp->anchorAx, Py), cdWMul(cp->anchorAy, Px));
			wA = cdWSub(wA, cdWMul(c->invIA, crossA));
			vAx = cdWSub(vAx, cdWMul(c->invMassA, Px));
			vAy = cdWSub(vAy, cdWMul(c->invMassA, Py));
			cdW crossB = cdWSub(cdWMul(cp->anchorBx, Py), cdWMul(cp->anchorBy, Px));
			wB = cdWAdd(wB, cdWMul(c->invIB, crossB));
			vBx = cdWAdd(vBx, cdWMul(c->invMassB, Px));
			vBy = cdWAdd(vBy, cdWMul(c->invMassB, Py));
		}
		wA = cdWSub(wA, cdWMul(c->invIA, c->rollingImpulse));
		wB = cdWAdd(wB, cdWMul(c->invIB, c->rollingImpulse));
		cd2ScatterVelocities(bodies, c->indexA, c->movesA, vAx, vAy, wA, a.dpx);
		cd2ScatterVelocities(bodies, c->indexB, c->movesB, vBx, vBy, wB, b.dpx);
	}
}

/* Inlined twice with a constant useBias (the solve and the relax pass): each loop keeps only its
 * own work, and fewer values compete for registers. */
static CD2_ALWAYS_INLINE void cd2SolveContactsWideImpl(cd2StepContext* context, int start, int end,
													   const bool useBias)
{
	cd2SolverBody* bodies = context->bodies;
	cdW inv_h = cdWSplat(context->inv_h);
	cdW minBias = cdWSplat(-context->contactPushMaxVelocity);
	cdW zero = cdWZero(), one = cdWSplat(CD_R(1.0));
	for (int i = start; i < end; ++i)
	{
		cd2ContactConstraintWide* c = context->wide + i;
		cd2BodyLanes a = cd2GatherBodies(bodies, c->indexA);
		cd2BodyLanes b = cd2GatherBodies(bodies, c->indexB);
		cdW mA = c->invMassA, iA = c->invIA, mB = c->invMassB, iB = c->invIB;
		cdW vAx = a.vx, vAy = a.vy, wA = a.w, vBx = b.vx, vBy = b.vy, wB = b.w;
		cdW nx = c->normalX, ny = c->normalY;
		cdW biasRate = useBias ? cdWMul(c->massScale, c->biasRate) : zero;
		cdW totalNormalImpulse = zero;
		for (int k = 0; k < 2; ++k)
		{
			cd2ContactPointWide* cp = c->points + k;
			cdW rAx = cp->anchorAx, rAy = cp->anchorAy, rBx = cp->anchorBx, rBy = cp->anchorBy;
			/* Current separation from the position deltas. */
			cdW prAx = cdWAdd(a.dpx, cdWSub(cdWMul(a.qc, rAx), cdWMul(a.qs, rAy)));
			cdW prAy = cdWAdd(a.dpy, cdWAdd(cdWMul(a.qs, rAx), cdWMul(a.qc, rAy)));
			cdW prBx = cdWAdd(b.dpx, cdWSub(cdWMul(b.qc, rBx), cdWMul(b.qs, rBy)));
			cdW prBy = cdWAdd(b.dpy, cdWAdd(cdWMul(b.qs, rBx), cdWMul(b.qc, rBy)));
			cdW s = cdWAdd(cdWAdd(cdWMul(cdWSub(prBx, prAx), nx), cdWMul(cdWSub(prBy, prAy), ny)),
						   cp->baseSeparation);
			cdW apart = cdWGreater(s, zero);
			cdW bias, massScale, impulseScale;
			if (useBias)
			{
				cdW softBias = cdWMax(cdWMul(biasRate, s), minBias);
				bias = cdWSelect(apart, cdWMul(s, inv_h), softBias);
				massScale = cdWSelect(apart, one, c->massScale);
				impulseScale = cdWSelect(apart, zero, c->impulseScale);
			}
			else
			{
				bias = cdWSelect(apart, cdWMul(s, inv_h), zero);
				massScale = one;
				impulseScale = zero;
			}
			cdW dvx = cdWSub(cdWSub(vBx, cdWMul(wB, rBy)), cdWSub(vAx, cdWMul(wA, rAy)));
			cdW dvy = cdWSub(cdWAdd(vBy, cdWMul(wB, rBx)), cdWAdd(vAy, cdWMul(wA, rAx)));
			cdW vn = cdWAdd(cdWMul(dvx, nx), cdWMul(dvy, ny));
			if (useBias)
			{
				cp->relativeVelocity = cdWMin(vn, cp->relativeVelocity);
			}
			/* -impulse: the same bits as the one-by-one solver's (x + -y is x - y). */
			cdW negImpulse = cdWAdd(cdWMul(cp->normalMass, cdWAdd(cdWMul(massScale, vn), bias)),
									cdWMul(impulseScale, cp->normalImpulse));
			cdW newImpulse = cdWMax(cdWSub(cp->normalImpulse, negImpulse), zero);
			cdW impulse = cdWSub(newImpulse, cp->normalImpulse);
			cp->normalImpulse = newImpulse;
			cp->maxNormalImpulse = cdWMax(cp->maxNormalImpulse, impulse);
			totalNormalImpulse = cdWAdd(totalNormalImpulse, newImpulse);
			cdW Px = cdWMul(impulse, nx), Py = cdWMul(impulse, ny);
			vAx = cdWSub(vAx, cdWMul(mA, Px));
			vAy = cdWSub(vAy, cdWMul(mA, Py));
			wA = cdWSub(wA, cdWMul(iA, cdWSub(cdWMul(rAx, Py), cdWMul(rAy, Px))));
			vBx = cdWAdd(vBx, cdWMul(mB, Px));
			vBy = cdWAdd(vBy, cdWMul(mB, Py));
			wB = cdWAdd(wB, cdWMul(iB, cdWSub(cdWMul(rBx, Py), cdWMul(rBy, Px))));
		}

		if (!useBias)
		{
			/* Friction and rolling resistance in the relax pass only (see contact_solver2.c). */
			cdW tx = ny, ty = cdWNeg(nx);
			for (int k = 0; k < 2; ++k)
			{
				cd2ContactPointWide* cp = c->points + k;
				cdW rAx = cp->anchorAx, rAy = cp->anchorAy, rBx = cp->anchorBx, rBy = cp->anchorBy;
				cdW dvx = cdWSub(cdWSub(vBx, cdWMul(wB, rBy)), cdWSub(vAx, cdWMul(wA, rAy)));
				cdW dvy = cdWSub(cdWAdd(vBy, cdWMul(wB, rBx)), cdWAdd(vAy, cdWMul(wA, rAx)));
				cdW vt = cdWSub(cdWAdd(cdWMul(dvx, tx), cdWMul(dvy, ty)), c->tangentSpeed);
				cdW maxFriction = cdWMul(c->friction, cp->normalImpulse);
				cdW newImpulse = cdWClamp(cdWSub(cp->tangentImpulse, cdWMul(cp->tangentMass, vt)),
										  cdWNeg(maxFriction), maxFriction);
				cdW impulse = cdWSub(newImpulse, cp->tangentImpulse);
				cp->tangentImpulse = newImpulse;
				cdW Px = cdWMul(impulse, tx), Py = cdWMul(impulse, ty);
				vAx = cdWSub(vAx, cdWMul(mA, Px));
				vAy = cdWSub(vAy, cdWMul(mA, Py));
				wA = cdWSub(wA, cdWMul(iA, cdWSub(cdWMul(rAx, Py), cdWMul(rAy, Px))));
				vBx = cdWAdd(vBx, cdWMul(mB, Px));
				vBy = cdWAdd(vBy, cdWMul(mB, Py));
				wB = cdWAdd(wB, cdWMul(iB, cdWSub(cdWMul(rBx, Py), cdWMul(rBy, Px))));
			}
			cdW rolling = cdWGreater(c->rollingResistance, zero);
			if (cdWAny(rolling))
			{
				cdW maxLambda = cdWMul(c->rollingResistance, totalNormalImpulse);
				cdW lambda = cdWMul(cdWNeg(c->rollingMass), cdWSub(wB, wA));
				cdW newLambda = cdWClamp(cdWAdd(c->rollingImpulse, lambda), cdWNeg(maxLambda), maxLambda);
				lambda = cdWSub(newLambda, c->rollingImpulse);
				c->rollingImpulse = cdWSelect(rolling, newLambda, c->rollingImpulse);
				wA = cdWSelect(rolling, cdWSub(wA, cdWMul(iA, lambda)), wA);
				wB = cdWSelect(rolling, cdWAdd(wB, cdWMul(iB, lambda)), wB);
			}
		}
		cd2ScatterVelocities(bodies, c->indexA, c->movesA, vAx, vAy, wA, a.dpx);
		cd2ScatterVelocities(bodies, c->indexB, c->movesB, vBx, vBy, wB, b.dpx);
	}
}

void cd2SolveContactsWide(cd2StepContext* context, int start, int end, bool useBias)
{
	if (useBias)
	{
		cd2SolveContactsWideImpl(context, start, end, true);
	}
	else
	{
		cd2SolveContactsWideImpl(context, start, end, false);
	}
}

/* Restitution of blocks [start, end) (one colour at most): cd2ApplyRestitution's arithmetic lane by
 * lane; a point that does not bounce (no restitution, too slow an approach, never pushed) leaves the
 * velocities and impulses exactly as they were. */
void cd2ApplyRestitutionWide(cd2StepContext* context, int start, int end)
{
	cd2SolverBody* bodies = context->bodies;
	cdW threshold = cdWSplat(-context->restitutionThreshold);
	cdW h = cdWSplat(context->h);
	cdW zero = cdWZero();
	int zeroIndex = context->bodyCount;
	for (int i = start; i < end; ++i)
	{
		cd2ContactConstraintWide* c = context->wide + i;
		if (!c->bounces)
		{
			continue;
		}
		/* Only points that were approaching fast enough and actually pushed bounce (what a point
		 * bounces on is its own, so both points are known before either is solved). */
		cdW bouncy = cdWNotEqual(c->restitution, zero);
		cdW applies[2];
		for (int k = 0; k < 2; ++k)
		{
			const cd2ContactPointWide* cp = c->points + k;
			cdW skip =
				cdWOr(cdWGreater(cp->relativeVelocity, threshold), cdWEqual(cp->maxNormalImpulse, zero));
			applies[k] = cdWAndNot(skip, bouncy);
		}
		if (!cdWAny(cdWOr(applies[0], applies[1])))
		{
			continue;
		}
		cd2BodyLanes a = cd2GatherBodies(bodies, c->indexA);
		cd2BodyLanes b = cd2GatherBodies(bodies, c->indexB);
		cdW mA = c->invMassA, iA = c->invIA, mB = c->invMassB, iB = c->invIB;
		cdW vAx = a.vx, vAy = a.vy, wA = a.w, vBx = b.vx, vBy = b.vy, wB = b.w;
		cdW nx = c->normalX, ny = c->normalY;
		/* B's acceleration relative to A's along the normal (the zero body's is zero), read only
		 * here: the pack leaves the accelerations alone. */
		cdReal accelerationLanes[CD_W];
		for (int lane = 0; lane < CD_W; ++lane)
		{
			cd2Vec n = {cdWGetLane(&nx, lane), cdWGetLane(&ny, lane)};
			cd2Vec accA =
				c->indexA[lane] == zeroIndex ? CD2_VEC_ZERO : context->accelerations[c->indexA[lane]];
			cd2Vec accB =
				c->indexB[lane] == zeroIndex ? CD2_VEC_ZERO : context->accelerations[c->indexB[lane]];
			accelerationLanes[lane] = cd2Dot(n, cd2Sub(accB, accA));
		}
		cdW normalAcceleration = cdWLoad(accelerationLanes);
		for (int k = 0; k < 2; ++k)
		{
			cd2ContactPointWide* cp = c->points + k;
			cdW apply = applies[k];
			if (!cdWAny(apply))
			{
				continue;
			}
			cdW rAx = cp->anchorAx, rAy = cp->anchorAy, rBx = cp->anchorBx, rBy = cp->anchorBy;
			cdW dvx = cdWSub(cdWSub(vBx, cdWMul(wB, rBy)), cdWSub(vAx, cdWMul(wA, rAy)));
			cdW dvy = cdWSub(cdWAdd(vBy, cdWMul(wB, rBx)), cdWAdd(vAy, cdWMul(wA, rAx)));
			cdW vn = cdWAdd(cdWMul(dvx, nx), cdWMul(dvy, ny));
			cdW approach = cdWMin(cdWAdd(cp->relativeVelocity, cdWMul(h, normalAcceleration)), zero);
			cdW negImpulse = cdWMul(cp->normalMass, cdWAdd(vn, cdWMul(c->restitution, approach)));
			cdW newImpulse = cdWMax(cdWSub(cp->normalImpulse, negImpulse), zero);
			cdW impulse = cdWSub(newImpulse, cp->normalImpulse);
			cp->normalImpulse = cdWSelect(apply, newImpulse, cp->normalImpulse);
			cp->maxNormalImpulse =
				cdWSelect(apply, cdWMax(cp->maxNormalImpulse, impulse), cp->maxNormalImpulse);
			cdW Px = cdWMul(impulse, nx), Py = cdWMul(impulse, ny);
			vAx = cdWSelect(apply, cdWSub(vAx, cdWMul(mA, Px)), vAx);
			vAy = cdWSelect(apply, cdWSub(vAy, cdWMul(mA, Py)), vAy);
			wA = cdWSelect(apply, cdWSub(wA, cdWMul(iA, cdWSub(cdWMul(rAx, Py), cdWMul(rAy, Px)))), wA);
			vBx = cdWSelect(apply, cdWAdd(vBx, cdWMul(mB, Px)), vBx);
			vBy = cdWSelect(apply, cdWAdd(vBy, cdWMul(mB, Py)), vBy);
			wB = cdWSelect(apply, cdWAdd(wB, cdWMul(iB, cdWSub(cdWMul(rBx, Py), cdWMul(rBy, Px)))), wB);
		}
		cd2ScatterVelocities(bodies, c->indexA, c->movesA, vAx, vAy, wA, a.dpx);
		cd2ScatterVelocities(bodies, c->indexB, c->movesB, vBx, vBy, wB, b.dpx);
	}
}

/* In blocks: how far ahead the store asks for the contact records it will write. */
#define CD2_STORE_PREFETCH_AHEAD 4

void cd2StoreContactsWide(cd2World* world, cd2StepContext* context, int startBlock, int endBlock)
{
	for (int i = startBlock; i < endBlock; ++i)
	{
		const cd2ContactConstraintWide* w = context->wide + i;
		/* The records of a few blocks ahead (their lines arrive while these are written). */
		if (i + CD2_STORE_PREFETCH_AHEAD < context->wideCount)
		{
			const cd2ContactConstraintWide* ahead = context->wide + i + CD2_STORE_PREFETCH_AHEAD;
			for (int lane = 0; lane < CD_W; ++lane)
			{
				if (ahead->contact[lane] >= 0)
				{
					cd2PrefetchContactForStore(world, ahead->contact[lane], context->storeApproach);
				}
			}
		}
		for (int lane = 0; lane < CD_W; ++lane)
		{
			if (w->contact[lane] < 0)
			{
				continue;
			}
			cd2Contact* contact = world->contacts.data + w->contact[lane];
			contact->rollingImpulse = cdWGetLane(&w->rollingImpulse, lane);
			for (int k = 0; k < w->pointCount[lane]; ++k)
			{
				const cd2ContactPointWide* wp = w->points + k;
				cd2ContactPoint* mp = contact->points + k;
				mp->normalImpulse = cdWGetLane(&wp->normalImpulse, lane);
				mp->tangentImpulse = cdWGetLane(&wp->tangentImpulse, lane);
				mp->maxNormalImpulse = cdWGetLane(&wp->maxNormalImpulse, lane);
				if (context->storeApproach)
				{
					contact->cache[k].relativeVelocity = cdWGetLane(&wp->relativeVelocity, lane);
				}
			}
		}
	}
}
