// Internal header of Stelkropp's C shim over Box2D v3 (see shim.c for the why and the API).
#pragma once

#include "box2d/box2d.h"
#include "box2d/constants.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#define S2_API __attribute__( ( visibility( "default" ) ) )

// the task system (shim_tasks.c)
typedef struct S2Pool S2Pool;
S2Pool* s2_pool_create( int workers );
void s2_pool_destroy( S2Pool* pool );
void s2_pool_reset( S2Pool* pool );
void* s2_enqueue( b2TaskCallback* fn, void* ctx, void* user );
void s2_finish( void* userTask, void* user );

typedef struct S2World
{
	b2WorldId id;
	b2BodyId ground;
	S2Pool* pool;
	b2BodyId* bodies;
	double* angle; // unwrapped body angle (Box2D keeps only cos/sin)
	b2Rot* lastRot;
	int bodyCount, bodyCap;
	b2JointId* joints;
	int jointCount, jointCap;
	int trackAngles;
	char error[256];
} S2World;

enum { SCHED_SERIAL = 0, SCHED_SHIM = 1, SCHED_BOX2D = 2 };

static inline b2Rot s2_rot( double angle )
{
	return (b2Rot){ (float)cos( angle ), (float)sin( angle ) };
}


static inline b2BodyId s2_body( S2World* w, int slot )
{
	return ( slot < 0 || slot >= w->bodyCount ) ? w->ground : w->bodies[slot];
}

// record builders (shim_ops.c); each returns the new slot (body, joint), 0 (shape) or -1
int s2_op_body( S2World* w, const double* a );
int s2_op_shape( S2World* w, const double* a, int m, const double* g );
int s2_op_joint( S2World* w, const double* a, int m, const double* q );
