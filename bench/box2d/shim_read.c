// Read-backs of the shim: body states, mass data, joint readouts, counters (see shim.c).
#include "shim.h"

S2_API int s2_body_count( S2World* w )
{
	return w->bodyCount;
}

S2_API int s2_joint_count( S2World* w )
{
	return w->jointCount;
}

// Per body slot, 10 numbers: origin x, y, angle, com velocity vx, vy, angular velocity,
// centre of mass x, y, valid (1/0), awake (1/0). Destroyed bodies read as NaN with valid 0.
S2_API void s2_read_bodies( S2World* w, double* out, int cap )
{
	int n = w->bodyCount < cap ? w->bodyCount : cap;
	for ( int i = 0; i < n; ++i )
	{
		double* o = out + 10 * i;
		b2BodyId b = w->bodies[i];
		if ( !b2Body_IsValid( b ) )
		{
			for ( int k = 0; k < 8; ++k ) o[k] = NAN;
			o[8] = 0.0, o[9] = 0.0;
			continue;
		}
		b2WorldTransform xf = b2Body_GetTransform( b );
		b2Vec2 v = b2Body_GetLinearVelocity( b );
		b2Pos c = b2Body_GetWorldCenter( b );
		double ang = atan2( xf.q.s, xf.q.c );
		if ( w->trackAngles )
		{
			ang = w->angle[i];
		}
		o[0] = xf.p.x, o[1] = xf.p.y, o[2] = ang;
		o[3] = v.x, o[4] = v.y, o[5] = b2Body_GetAngularVelocity( b );
		o[6] = c.x, o[7] = c.y, o[8] = 1.0, o[9] = b2Body_IsAwake( b ) ? 1.0 : 0.0;
	}
}

// Per body slot, 4 numbers: mass (kg), rotational inertia about the centre of mass (kg m^2),
// local centre of mass x, y (body frame).
S2_API void s2_read_mass( S2World* w, double* out, int cap )
{
	int n = w->bodyCount < cap ? w->bodyCount : cap;
	for ( int i = 0; i < n; ++i )
	{
		double* o = out + 4 * i;
		b2BodyId b = w->bodies[i];
		if ( !b2Body_IsValid( b ) )
		{
			o[0] = o[1] = o[2] = o[3] = NAN;
			continue;
		}
		b2MassData md = b2Body_GetMassData( b );
		o[0] = md.mass, o[1] = md.rotationalInertia, o[2] = md.center.x, o[3] = md.center.y;
	}
}

// Per joint slot, 9 numbers: reaction force x, y (N, on body B), reaction torque (N m),
// linear separation (m), angular separation (rad), the kind's coordinate (revolute angle,
// prismatic/wheel translation, distance length; else 0), its rate, motor torque/force, valid.
S2_API void s2_read_joints( S2World* w, double* out, int cap )
{
	int n = w->jointCount < cap ? w->jointCount : cap;
	for ( int i = 0; i < n; ++i )
	{
		double* o = out + 9 * i;
		b2JointId j = w->joints[i];
		if ( !b2Joint_IsValid( j ) )
		{
			for ( int k = 0; k < 8; ++k ) o[k] = NAN;
			o[8] = 0.0;
			continue;
		}
		b2Vec2 f = b2Joint_GetConstraintForce( j );
		o[0] = f.x, o[1] = f.y, o[2] = b2Joint_GetConstraintTorque( j );
		o[3] = b2Joint_GetLinearSeparation( j ), o[4] = b2Joint_GetAngularSeparation( j );
		o[5] = o[6] = o[7] = 0.0, o[8] = 1.0;
		switch ( b2Joint_GetType( j ) )
		{
			case b2_revoluteJoint:
				o[5] = b2RevoluteJoint_GetAngle( j );
				o[6] = b2Body_GetAngularVelocity( b2Joint_GetBodyB( j ) ) - b2Body_GetAngularVelocity( b2Joint_GetBodyA( j ) );
				o[7] = b2RevoluteJoint_GetMotorTorque( j );
				break;
			case b2_prismaticJoint:
				o[5] = b2PrismaticJoint_GetTranslation( j ), o[6] = b2PrismaticJoint_GetSpeed( j );
				o[7] = b2PrismaticJoint_GetMotorForce( j );
				break;
			case b2_wheelJoint:
				o[7] = b2WheelJoint_GetMotorTorque( j );
				break;
			case b2_distanceJoint:
				o[5] = b2DistanceJoint_GetCurrentLength( j ), o[7] = b2DistanceJoint_GetMotorForce( j );
				break;
			default:
				break;
		}
	}
}

// bodies, shapes, contacts, joints, islands, awake bodies, touching contacts (manifolds with points)
S2_API void s2_counters( S2World* w, int* out )
{
	b2Counters c = b2World_GetCounters( w->id );
	out[0] = c.bodyCount, out[1] = c.shapeCount, out[2] = c.contactCount, out[3] = c.jointCount;
	out[4] = c.islandCount, out[5] = b2World_GetAwakeBodyCount( w->id );
	int touching = 0, cap = 0;
	b2ContactData* buf = NULL;
	for ( int i = 0; i < w->bodyCount; ++i )
	{
		b2BodyId b = w->bodies[i];
		if ( !b2Body_IsValid( b ) )
		{
			continue;
		}
		int need = b2Body_GetContactCapacity( b );
		if ( need > cap )
		{
			cap = need;
			buf = realloc( buf, cap * sizeof( b2ContactData ) );
		}
		int k = need > 0 ? b2Body_GetContactData( b, buf, need ) : 0;
		for ( int m = 0; m < k; ++m )
		{
			// count each touching contact once: on the body that owns shape A
			b2BodyId ba = b2Shape_GetBody( buf[m].shapeIdA );
			if ( buf[m].manifold.pointCount > 0 && B2_ID_EQUALS( ba, b ) )
			{
				touching += 1;
			}
		}
	}
	free( buf );
	out[6] = touching;
}

