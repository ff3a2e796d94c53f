/* libFuzzer target: decodes the input into a broadphase type, a dimension and a sequence of
 * operations (create, small move, teleport, destroy, rebuild, pairs, box query, ray cast),
 * replays them and compares every answer with the brute-force oracle of tests/broad_oracle.h.
 * Aborts on any mismatch or failed validation. Coordinates come from a small lattice so that
 * boxes overlap, touch and coincide often; special bytes inject NaN, infinities, huge values and
 * inverted boxes. */
#include "broad_oracle.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

typedef struct Reader
{
	const uint8_t* data;
	size_t size, at;
} Reader;

static uint8_t Byte(Reader* r)
{
	return r->at < r->size ? r->data[r->at++] : 0;
}

static cdReal Coord(Reader* r)
{
	uint8_t b = Byte(r);
	switch (b)
	{
		case 250:
			return (cdReal)NAN;
		case 251:
			return (cdReal)INFINITY;
		case 252:
			return (cdReal)-INFINITY;
		case 253:
			return CD_R(1e9);
		case 254:
			return CD_R(-1e9);
		case 255:
			return CD_R(1e30);
		default:
			return (cdReal)((int)b - 125) * CD_R(0.25);
	}
}

static OBox ReadBox(Reader* r, int dim)
{
	OBox b;
	memset(&b, 0, sizeof(b));
	for (int i = 0; i < dim; ++i)
	{
		b.min[i] = Coord(r);
		uint8_t size = Byte(r);
		b.max[i] = b.min[i] + (size >= 250 ? CD_R(-1.0) : (cdReal)(size % 32) * CD_R(0.25));
	}
	return b;
}

static void Fail(const Oracle* o, const char* what, size_t at)
{
	fprintf(stderr, "fuzz_broadphase: %s %dD: %s at input byte %zu: %s\n", cdGetBroadPhaseTypeName(o->type),
			o->dim, what, at, o->error);
	abort();
}

enum
{
	FUZZ_MAX_LIVE = 300,
	FUZZ_MAX_OPS = 3000
};

static Oracle s_oracle;
static OBox s_tight[ORACLE_MAX_PROXIES];
static int s_ids[ORACLE_MAX_PROXIES];

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	Reader r = {data, size, 0};
	Oracle* o = &s_oracle;
	uint8_t head = Byte(&r);
	int dim = 2 + (head & 1);
	cdBroadPhaseType type = (cdBroadPhaseType)((head >> 1) % CD_BROADPHASE_TYPE_COUNT);
	cdReal margin = (cdReal)((head >> 3) & 3) * CD_R(0.25);
	cdReal multiplier = (cdReal)((head >> 5) & 3);
	if (!OracleInit(o, dim, type, margin, multiplier))
	{
		return 0;
	}
	int live = 0;
	uint64_t nextData = 1;
	for (int op = 0; op < FUZZ_MAX_OPS && r.at < r.size; ++op)
	{
		size_t at = r.at;
		uint8_t code = Byte(&r);
		bool ok = true;
		switch (code % 10)
		{
			case 0:
			case 1:
			{
				OBox b = ReadBox(&r, dim);
				int id;
				if (live < FUZZ_MAX_LIVE)
				{
					ok = OracleCreate(o, b, nextData++, &id);
					if (ok && id >= 0)
					{
						s_ids[live++] = id;
						s_tight[id] = b;
					}
				}
				break;
			}
			case 2:
			case 3:
			case 4:
			{
				if (live == 0)
				{
					break;
				}
				int id = s_ids[Byte(&r) % live];
				cdReal d[3] = {CD_R(0.0), CD_R(0.0), CD_R(0.0)};
				OBox b = s_tight[id];
				bool teleport = code % 10 == 4;
				if (teleport)
				{
					b = ReadBox(&r, dim);
				}
				for (int i = 0; i < dim; ++i)
				{
					d[i] = (cdReal)((int)Byte(&r) - 128) * CD_R(0.0625);
					if (!teleport)
					{
						b.min[i] += d[i];
						b.max[i] += d[i];
					}
				}
				ok = OracleMove(o, id, b, d);
				if (OracleBoxValid(o, b))
				{
					s_tight[id] = b;
				}
				break;
			}
			case 5:
			{
				if (live == 0)
				{
					break;
				}
				int k = Byte(&r) % live;
				ok = OracleDestroy(o, s_ids[k]);
				s_ids[k] = s_ids[--live];
				break;
			}
			case 6:
				ok = OracleFindAllPairs(o) && OracleUpdatePairs(o);
				break;
			case 7:
			{
				OBox b = ReadBox(&r, dim);
				if (OracleBoxValid(o, b))
				{
					ok = OracleQueryBox(o, b, Byte(&r) % 4);
				}
				break;
			}
			case 8:
			{
				cdReal origin[3] = {CD_R(0.0), CD_R(0.0), CD_R(0.0)},
					   translation[3] = {CD_R(0.0), CD_R(0.0), CD_R(0.0)};
				bool finite = true;
				for (int i = 0; i < dim; ++i)
				{
					origin[i] = Coord(&r);
					translation[i] = Coord(&r) * CD_R(4.0);
					finite = finite && isfinite(origin[i]) && isfinite(translation[i]) &&
							 cdAbs(origin[i]) < CD_R(1e6) && cdAbs(translation[i]) < CD_R(1e6);
				}
				if (finite)
				{
					ok = OracleRayCast(o, origin, translation, (code & 16) != 0);
				}
				break;
			}
			default:
				if (code >= 200 && live > 0)
				{
					/* Several moves in one MoveProxies call (ids may repeat). */
					int count = 1 + Byte(&r) % 16;
					int ids[16];
					OBox boxes[16];
					cdReal d[16][3];
					for (int k = 0; k < count; ++k)
					{
						int id = s_ids[Byte(&r) % live];
						uint8_t how = Byte(&r);
						OBox b = (how & 1) ? ReadBox(&r, dim) : s_tight[id];
						for (int i = 0; i < 3; ++i)
						{
							d[k][i] = i < dim ? (cdReal)((int)Byte(&r) - 128) * CD_R(0.0625) : CD_R(0.0);
							if (!(how & 1) && i < dim)
							{
								b.min[i] += d[k][i];
								b.max[i] += d[k][i];
							}
						}
						ids[k] = id;
						boxes[k] = b;
						if (OracleBoxValid(o, b))
						{
							s_tight[id] = b;
						}
					}
					ok = OracleMoveMany(o, count, ids, boxes, (const cdReal(*)[3])d);
					break;
				}
				ok = OracleRebuild(o);
				break;
		}
		if (!ok)
		{
			Fail(o, "operation", at);
		}
		if (!OracleValidate(o))
		{
			Fail(o, "validation", at);
		}
	}
	if (!OracleFindAllPairs(o) || !OracleUpdatePairs(o))
	{
		Fail(o, "final pairs", r.at);
	}
	OracleFree(o);
	return 0;
}
