// Stelkropp's small C API over Box2D v3, loaded from Python with ctypes (bench/box2d/engine.py).
//
// Why a command stream: a bench scene has up to ~20,000 bodies, shapes and joints, and the
// rain benchmark creates and destroys hundreds of them every eighth step inside the timed loop.
// One ctypes call per item would cost microseconds each, so Python packs a whole batch into one
// array of doubles and s2_exec() builds it in C (layout: see the OP_* comments and engine.py).
//
// Bodies and joints are addressed by slot: the order in which this world created them. Slot -1 is
// a static ground body at the origin that joints use for "attached to the world".
#include "shim.h"

#include <string.h>

// params: gx, gy, sleeping, continuous, workers, scheduler, contact_hertz, contact_damping,
// contact_speed, restitution_threshold, max_linear_speed, contact_softening, track_angles,
// hit_event_threshold (a negative value keeps Box2D's default)
S2_API S2World* s2_world_create( const double* p, int n )
{
	if ( n < 14 )
	{
		return NULL;
	}
	b2WorldDef def = b2DefaultWorldDef();
	def.gravity = (b2Vec2){ (float)p[0], (float)p[1] };
	def.enableSleep = p[2] != 0.0;
	def.enableContinuous = p[3] != 0.0;
	int workers = (int)p[4] < 1 ? 1 : (int)p[4];
	int sched = (int)p[5];
	if ( p[6] >= 0.0 ) def.contactHertz = (float)p[6];
	if ( p[7] >= 0.0 ) def.contactDampingRatio = (float)p[7];
	if ( p[8] >= 0.0 ) def.contactSpeed = (float)p[8];
	if ( p[9] >= 0.0 ) def.restitutionThreshold = (float)p[9];
	if ( p[10] >= 0.0 ) def.maximumLinearSpeed = (float)p[10];
	def.enableContactSoftening = p[11] != 0.0;
	if ( p[13] >= 0.0 ) def.hitEventThreshold = (float)p[13];

	S2World* w = calloc( 1, sizeof( S2World ) );
	w->trackAngles = p[12] != 0.0;
	if ( workers > 1 && sched == SCHED_SHIM )
	{
		w->pool = s2_pool_create( workers );
		def.workerCount = workers;
		def.enqueueTask = s2_enqueue;
		def.finishTask = s2_finish;
		def.userTaskContext = w->pool;
	}
	else if ( workers > 1 && sched == SCHED_BOX2D )
	{
		def.workerCount = workers; // Box2D's built-in scheduler (what its benchmark app uses)
	}
	else
	{
		def.workerCount = 1;
	}
	w->id = b2CreateWorld( &def );
	b2BodyDef bd = b2DefaultBodyDef();
	w->ground = b2CreateBody( w->id, &bd );
	return w;
}

S2_API void s2_world_destroy( S2World* w )
{
	if ( w == NULL )
	{
		return;
	}
	b2DestroyWorld( w->id );
	if ( w->pool )
	{
		s2_pool_destroy( w->pool );
	}
	free( w->bodies );
	free( w->angle );
	free( w->lastRot );
	free( w->joints );
	free( w );
}

S2_API const char* s2_error( S2World* w )
{
	return w->error;
}
enum { OP_BODY = 1, OP_SHAPE = 2, OP_JOINT = 3, OP_DESTROY_BODY = 4, OP_DESTROY_JOINT = 5, OP_VELOCITY = 6 };

// Runs a command stream. Each record: opcode, then its fixed fields, then (shape, joint) a count
// m and m numbers. Writes the slot of every body and joint created to out (in order) and
// returns how many; -1 on an error (s2_error() says which record).
S2_API int s2_exec( S2World* w, const double* c, int n, int* out, int outCap )
{
	int i = 0, made = 0, record = 0;
	while ( i < n )
	{
		int op = (int)c[i];
		int slot = -2;
		if ( op == OP_BODY && i + 13 <= n )
		{
			slot = s2_op_body( w, c + i + 1 );
			i += 13;
		}
		else if ( op == OP_SHAPE && i + 16 <= n && i + 16 + (int)c[i + 15] <= n )
		{
			int m = (int)c[i + 15];
			if ( s2_op_shape( w, c + i + 1, m, c + i + 16 ) < 0 )
			{
				return -1;
			}
			i += 16 + m;
		}
		else if ( op == OP_JOINT && i + 14 <= n && i + 14 + (int)c[i + 13] <= n )
		{
			int m = (int)c[i + 13];
			slot = s2_op_joint( w, c + i + 1, m, c + i + 14 );
			if ( slot < 0 )
			{
				return -1;
			}
			i += 14 + m;
		}
		else if ( op == OP_DESTROY_BODY && i + 2 <= n )
		{
			int b = (int)c[i + 1];
			if ( b >= 0 && b < w->bodyCount && b2Body_IsValid( w->bodies[b] ) )
			{
				b2DestroyBody( w->bodies[b] ); // also destroys its joints
			}
			i += 2;
		}
		else if ( op == OP_VELOCITY && i + 5 <= n )
		{
			// after the shapes: Box2D keeps the origin's velocity while shapes move the centre of
			// mass, so the centre-of-mass velocity of a description is set once the mass is known
			b2BodyId b = s2_body( w, (int)c[i + 1] );
			b2Body_SetLinearVelocity( b, (b2Vec2){ (float)c[i + 2], (float)c[i + 3] } );
			b2Body_SetAngularVelocity( b, (float)c[i + 4] );
			i += 5;
		}
		else if ( op == OP_DESTROY_JOINT && i + 2 <= n )
		{
			int j = (int)c[i + 1];
			if ( j >= 0 && j < w->jointCount && b2Joint_IsValid( w->joints[j] ) )
			{
				b2DestroyJoint( w->joints[j] );
			}
			i += 2;
		}
		else
		{
			snprintf( w->error, sizeof w->error, "record %d at %d: bad opcode %d or truncated record", record, i, op );
			return -1;
		}
		if ( slot >= 0 && made < outCap )
		{
			out[made++] = slot;
		}
		record += 1;
	}
	return made;
}


static void s2_track( S2World* w )
{
	b2BodyEvents ev = b2World_GetBodyEvents( w->id );
	for ( int i = 0; i < ev.moveCount; ++i )
	{
		int slot = (int)(intptr_t)ev.moveEvents[i].userData - 1;
		if ( slot < 0 || slot >= w->bodyCount )
		{
			continue;
		}
		b2Rot a = w->lastRot[slot], b = ev.moveEvents[i].transform.q;
		// rotation increment between steps: atan2(a x b, a . b), always < B2_MAX_ROTATION per sub-step
		w->angle[slot] += atan2( (double)a.c * b.s - (double)a.s * b.c, (double)a.c * b.c + (double)a.s * b.s );
		w->lastRot[slot] = b;
	}
}

S2_API void s2_step( S2World* w, double dt, int substeps, int count )
{
	for ( int k = 0; k < count; ++k )
	{
		if ( w->pool )
		{
			s2_pool_reset( w->pool );
		}
		b2World_Step( w->id, (float)dt, substeps );
		if ( w->trackAngles )
		{
			s2_track( w );
		}
	}
}

S2_API void s2_set_velocity( S2World* w, int slot, double vx, double vy, double av )
{
	b2BodyId b = s2_body( w, slot );
	b2Body_SetLinearVelocity( b, (b2Vec2){ (float)vx, (float)vy } );
	b2Body_SetAngularVelocity( b, (float)av );
}

// Kinematic drive: Box2D sets the velocity that reaches the target pose in one step.
S2_API void s2_set_target( S2World* w, int slot, double x, double y, double angle, double dt )
{
	b2WorldTransform t = { (b2Pos){ (float)x, (float)y }, s2_rot( angle ) };
	b2Body_SetTargetTransform( s2_body( w, slot ), t, (float)dt, true );
}

// Moves a joint's frame A (a mouse joint's target on the ground body).
S2_API void s2_set_frame_a( S2World* w, int joint, double x, double y, double angle )
{
	b2JointId j = w->joints[joint];
	b2Joint_SetLocalFrameA( j, (b2Transform){ { (float)x, (float)y }, s2_rot( angle ) } );
	b2Joint_WakeBodies( j );
}

S2_API double s2_last_step_ms( S2World* w )
{
	return b2World_GetProfile( w->id ).step;
}

