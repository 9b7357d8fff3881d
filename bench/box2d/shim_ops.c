// Record builders of the shim's command stream: bodies, shapes, joints (see shim.c).
#include "shim.h"

static int s2_push_body( S2World* w, b2BodyId id, double angle )
{
	if ( w->bodyCount == w->bodyCap )
	{
		w->bodyCap = w->bodyCap ? 2 * w->bodyCap : 256;
		w->bodies = realloc( w->bodies, w->bodyCap * sizeof( b2BodyId ) );
		w->angle = realloc( w->angle, w->bodyCap * sizeof( double ) );
		w->lastRot = realloc( w->lastRot, w->bodyCap * sizeof( b2Rot ) );
	}
	int slot = w->bodyCount++;
	w->bodies[slot] = id;
	w->angle[slot] = angle;
	w->lastRot[slot] = b2Body_GetRotation( id );
	return slot;
}

static int s2_push_joint( S2World* w, b2JointId id )
{
	if ( w->jointCount == w->jointCap )
	{
		w->jointCap = w->jointCap ? 2 * w->jointCap : 256;
		w->joints = realloc( w->joints, w->jointCap * sizeof( b2JointId ) );
	}
	w->joints[w->jointCount] = id;
	return w->jointCount++;
}

// OP_BODY: type, x, y, angle, vx, vy, w, flags, gravity_scale, linear_damping, angular_damping,
// sleep_threshold. flags: 1 bullet, 2 never sleeps, 4 starts asleep, 8 fast rotation allowed.
int s2_op_body( S2World* w, const double* a )
{
	b2BodyDef d = b2DefaultBodyDef();
	d.type = (b2BodyType)(int)a[0];
	d.position = (b2Pos){ (float)a[1], (float)a[2] };
	d.rotation = s2_rot( a[3] );
	d.linearVelocity = (b2Vec2){ (float)a[4], (float)a[5] };
	d.angularVelocity = (float)a[6];
	int flags = (int)a[7];
	d.isBullet = ( flags & 1 ) != 0;
	d.enableSleep = ( flags & 2 ) == 0;
	d.isAwake = ( flags & 4 ) == 0;
	d.allowFastRotation = ( flags & 8 ) != 0;
	d.gravityScale = (float)a[8];
	d.linearDamping = (float)a[9];
	d.angularDamping = (float)a[10];
	if ( a[11] >= 0.0 ) d.sleepThreshold = (float)a[11];
	int slot = w->bodyCount;
	d.userData = (void*)(intptr_t)( slot + 1 );
	return s2_push_body( w, b2CreateBody( w->id, &d ), a[3] );
}

static uint64_t s2_bits( double hi, double lo )
{
	if ( hi < 0.0 )
	{
		return UINT64_MAX;
	}
	return ( (uint64_t)hi << 32 ) | (uint64_t)lo;
}

// A convex polygon from counter-clockwise points (the caller checks convexity and winding).
static b2Polygon s2_polygon( const double* xy, int count, float radius )
{
	b2Polygon poly = { 0 };
	poly.count = count;
	poly.radius = radius;
	double ox = xy[0], oy = xy[1], area = 0.0, cx = 0.0, cy = 0.0;
	for ( int i = 0; i < count; ++i )
	{
		poly.vertices[i] = (b2Vec2){ (float)xy[2 * i], (float)xy[2 * i + 1] };
	}
	for ( int i = 0; i < count; ++i )
	{
		int j = ( i + 1 ) % count;
		double ex = xy[2 * j] - xy[2 * i], ey = xy[2 * j + 1] - xy[2 * i + 1];
		double len = sqrt( ex * ex + ey * ey );
		poly.normals[i] = (b2Vec2){ (float)( ey / len ), (float)( -ex / len ) };
		// centroid relative to the first vertex (triangle fan), as for any polygon area formula
		double ax = xy[2 * i] - ox, ay = xy[2 * i + 1] - oy, bx = xy[2 * j] - ox, by = xy[2 * j + 1] - oy;
		double t = 0.5 * ( ax * by - ay * bx );
		area += t;
		cx += t * ( ax + bx ) / 3.0;
		cy += t * ( ay + by ) / 3.0;
	}
	poly.centroid = (b2Vec2){ (float)( ox + cx / area ), (float)( oy + cy / area ) };
	return poly;
}

// OP_SHAPE: body, kind, density, friction, restitution, rolling_resistance, tangent_speed,
// cat_hi, cat_lo, mask_hi, mask_lo, group, flags, radius, m, then m numbers of geometry.
// kinds: 0 circle (cx, cy), 1 capsule (ax, ay, bx, by), 2 segment (ax, ay, bx, by),
// 3 polygon (x0, y0, ...; CCW convex, <= 8 points), 4 box (hx, hy, cx, cy, angle),
// 5 chain (x0, y0, ...; >= 4 points). flags: 1 sensor, 2 hit events, 4 sensor events,
// 8 contact events, 16 loop (chain), 32 custom: do not update body mass.
int s2_op_shape( S2World* w, const double* a, int m, const double* g )
{
	b2BodyId body = s2_body( w, (int)a[0] );
	int kind = (int)a[1];
	int flags = (int)a[12];
	float radius = (float)a[13];
	b2SurfaceMaterial mat = b2DefaultSurfaceMaterial();
	mat.friction = (float)a[3];
	mat.restitution = (float)a[4];
	mat.rollingResistance = (float)a[5];
	mat.tangentSpeed = (float)a[6];
	b2Filter filter = { s2_bits( a[7], a[8] ), s2_bits( a[9], a[10] ), (int)a[11] };
	if ( kind == 5 )
	{
		int count = m / 2;
		b2Vec2* pts = malloc( count * sizeof( b2Vec2 ) );
		for ( int i = 0; i < count; ++i )
		{
			pts[i] = (b2Vec2){ (float)g[2 * i], (float)g[2 * i + 1] };
		}
		b2ChainDef cd = b2DefaultChainDef();
		cd.points = pts;
		cd.count = count;
		cd.materials = &mat;
		cd.materialCount = 1;
		cd.filter = filter;
		cd.isLoop = ( flags & 16 ) != 0;
		cd.enableSensorEvents = ( flags & 4 ) != 0;
		b2CreateChain( body, &cd );
		free( pts );
		return 0;
	}
	b2ShapeDef sd = b2DefaultShapeDef();
	sd.material = mat;
	sd.density = (float)a[2];
	sd.filter = filter;
	sd.isSensor = ( flags & 1 ) != 0;
	sd.enableHitEvents = ( flags & 2 ) != 0;
	sd.enableSensorEvents = ( flags & 4 ) != 0;
	sd.enableContactEvents = ( flags & 8 ) != 0;
	sd.updateBodyMass = ( flags & 32 ) == 0;
	if ( kind == 0 )
	{
		b2Circle c = { { (float)g[0], (float)g[1] }, radius };
		b2CreateCircleShape( body, &sd, &c );
	}
	else if ( kind == 1 )
	{
		b2Capsule c = { { (float)g[0], (float)g[1] }, { (float)g[2], (float)g[3] }, radius };
		b2CreateCapsuleShape( body, &sd, &c );
	}
	else if ( kind == 2 )
	{
		b2Segment s = { { (float)g[0], (float)g[1] }, { (float)g[2], (float)g[3] } };
		b2CreateSegmentShape( body, &sd, &s );
	}
	else if ( kind == 3 )
	{
		int count = m / 2;
		if ( count < 3 || count > B2_MAX_POLYGON_VERTICES )
		{
			snprintf( w->error, sizeof w->error, "polygon needs 3..%d points, got %d", B2_MAX_POLYGON_VERTICES, count );
			return -1;
		}
		b2Polygon poly = s2_polygon( g, count, radius );
		b2CreatePolygonShape( body, &sd, &poly );
	}
	else if ( kind == 4 )
	{
		b2Polygon box = b2MakeOffsetRoundedBox( (float)g[0], (float)g[1], (b2Vec2){ (float)g[2], (float)g[3] },
												s2_rot( g[4] ), radius );
		b2CreatePolygonShape( body, &sd, &box );
	}
	else
	{
		snprintf( w->error, sizeof w->error, "unknown shape kind %d", kind );
		return -1;
	}
	return 0;
}

// OP_JOINT: kind, bodyA, bodyB, frameA (x, y, angle), frameB (x, y, angle), collide,
// constraint_hertz, constraint_damping (negative: default), m, then m kind parameters.
// kinds: 0 revolute, 1 prismatic, 2 weld, 3 distance, 4 wheel, 5 motor, 6 filter.
int s2_op_joint( S2World* w, const double* a, int m, const double* q )
{
	b2JointDef base = { 0 };
	int kind = (int)a[0];
	base.bodyIdA = s2_body( w, (int)a[1] );
	base.bodyIdB = s2_body( w, (int)a[2] );
	base.localFrameA = (b2Transform){ { (float)a[3], (float)a[4] }, s2_rot( a[5] ) };
	base.localFrameB = (b2Transform){ { (float)a[6], (float)a[7] }, s2_rot( a[8] ) };
	base.collideConnected = a[9] != 0.0;
	static const int need[7] = { 10, 10, 4, 12, 9, 11, 0 };
	if ( kind < 0 || kind > 6 || m < need[kind] )
	{
		snprintf( w->error, sizeof w->error, "joint kind %d needs %d parameters, got %d", kind, kind >= 0 && kind <= 6 ? need[kind] : -1, m );
		return -1;
	}
	b2JointId id;
#define S2_BASE( def )                                                                                                   \
	do                                                                                                                   \
	{                                                                                                                    \
		b2JointDef keep = def.base;                                                                                      \
		def.base = base;                                                                                                 \
		def.base.userData = NULL;                                                                                        \
		def.base.forceThreshold = keep.forceThreshold;                                                                   \
		def.base.torqueThreshold = keep.torqueThreshold;                                                                 \
		def.base.drawScale = keep.drawScale;                                                                             \
		def.base.constraintHertz = a[10] >= 0.0 ? (float)a[10] : keep.constraintHertz;                                   \
		def.base.constraintDampingRatio = a[11] >= 0.0 ? (float)a[11] : keep.constraintDampingRatio;                     \
	}                                                                                                                    \
	while ( 0 )
	if ( kind == 0 )
	{
		b2RevoluteJointDef d = b2DefaultRevoluteJointDef();
		S2_BASE( d );
		d.enableSpring = q[0] != 0.0, d.hertz = (float)q[1], d.dampingRatio = (float)q[2], d.targetAngle = (float)q[3];
		d.enableLimit = q[4] != 0.0, d.lowerAngle = (float)q[5], d.upperAngle = (float)q[6];
		d.enableMotor = q[7] != 0.0, d.maxMotorTorque = (float)q[8], d.motorSpeed = (float)q[9];
		id = b2CreateRevoluteJoint( w->id, &d );
	}
	else if ( kind == 1 )
	{
		b2PrismaticJointDef d = b2DefaultPrismaticJointDef();
		S2_BASE( d );
		d.enableSpring = q[0] != 0.0, d.hertz = (float)q[1], d.dampingRatio = (float)q[2];
		d.targetTranslation = (float)q[3];
		d.enableLimit = q[4] != 0.0, d.lowerTranslation = (float)q[5], d.upperTranslation = (float)q[6];
		d.enableMotor = q[7] != 0.0, d.maxMotorForce = (float)q[8], d.motorSpeed = (float)q[9];
		id = b2CreatePrismaticJoint( w->id, &d );
	}
	else if ( kind == 2 )
	{
		b2WeldJointDef d = b2DefaultWeldJointDef();
		S2_BASE( d );
		d.linearHertz = (float)q[0], d.angularHertz = (float)q[1];
		d.linearDampingRatio = (float)q[2], d.angularDampingRatio = (float)q[3];
		id = b2CreateWeldJoint( w->id, &d );
	}
	else if ( kind == 3 )
	{
		b2DistanceJointDef d = b2DefaultDistanceJointDef();
		S2_BASE( d );
		d.length = (float)q[0];
		d.enableSpring = q[1] != 0.0, d.hertz = (float)q[2], d.dampingRatio = (float)q[3];
		if ( q[4] > -1e37 ) d.lowerSpringForce = (float)q[4];
		if ( q[5] < 1e37 ) d.upperSpringForce = (float)q[5];
		d.enableLimit = q[6] != 0.0, d.minLength = (float)q[7], d.maxLength = (float)q[8];
		d.enableMotor = q[9] != 0.0, d.maxMotorForce = (float)q[10], d.motorSpeed = (float)q[11];
		id = b2CreateDistanceJoint( w->id, &d );
	}
	else if ( kind == 4 )
	{
		b2WheelJointDef d = b2DefaultWheelJointDef();
		S2_BASE( d );
		d.enableSpring = q[0] != 0.0, d.hertz = (float)q[1], d.dampingRatio = (float)q[2];
		d.enableLimit = q[3] != 0.0, d.lowerTranslation = (float)q[4], d.upperTranslation = (float)q[5];
		d.enableMotor = q[6] != 0.0, d.maxMotorTorque = (float)q[7], d.motorSpeed = (float)q[8];
		id = b2CreateWheelJoint( w->id, &d );
	}
	else if ( kind == 5 )
	{
		b2MotorJointDef d = b2DefaultMotorJointDef();
		S2_BASE( d );
		d.linearVelocity = (b2Vec2){ (float)q[0], (float)q[1] }, d.maxVelocityForce = (float)q[2];
		d.angularVelocity = (float)q[3], d.maxVelocityTorque = (float)q[4];
		d.linearHertz = (float)q[5], d.linearDampingRatio = (float)q[6], d.maxSpringForce = (float)q[7];
		d.angularHertz = (float)q[8], d.angularDampingRatio = (float)q[9], d.maxSpringTorque = (float)q[10];
		id = b2CreateMotorJoint( w->id, &d );
	}
	else
	{
		b2FilterJointDef d = b2DefaultFilterJointDef();
		S2_BASE( d );
		id = b2CreateFilterJoint( w->id, &d );
	}
#undef S2_BASE
	return s2_push_joint( w, id );
}

