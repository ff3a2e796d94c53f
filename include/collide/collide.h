/* collide: collision detection and rigid-body physics in 2D and 3D. Includes every public
 * header. */
#ifndef COLLIDE_COLLIDE_H
#define COLLIDE_COLLIDE_H

#include "collide/base.h"
#include "collide/math2.h"
#include "collide/math3.h"
#include "collide/geometry2.h"
#include "collide/geometry3.h"
#include "collide/query2.h"
#include "collide/query3.h"
#include "collide/manifold2.h"
#include "collide/manifold3.h"
#include "collide/chain2.h"
#include "collide/mesh3.h"
#include "collide/broad.h"
#include "collide/cast.h"
#include "collide/world2.h"

#endif
