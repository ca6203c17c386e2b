#pragma once
// Bullet's multibody world without the one piece of its step that only continuous collision
// detection reads. Internal to sim/ (DynamicsWorld.cpp); the Bullet types are only declared here.

#include <memory>

class btBroadphaseInterface;
class btCollisionConfiguration;
class btDispatcher;
class btMultiBodyConstraintSolver;
class btMultiBodyDynamicsWorld;

namespace parksim {

/// A btMultiBodyDynamicsWorld (Bullet 3.24) whose step skips predicting each awake multibody's
/// pose at the end of the step (btMultiBody::predictPositionsMultiDof and its colliders'
/// interpolation transforms, ~2 k instructions a step for the robot). Those are read only by
/// continuous collision detection (time of impact; parksim dispatches discretely), by rigid
/// bodies' swept bounding boxes (never a multibody's link), by a kinematic base's velocity
/// (btMultiBody::saveKinematicState; parksim has none) and by debug drawing, so every result is
/// bit-identical. With continuous dispatch or a kinematic base it steps as Bullet does. Sleeping
/// multibodies still have their velocities cleared, as Bullet's step does.
std::unique_ptr<btMultiBodyDynamicsWorld> makeDiscreteMultiBodyWorld(
    btDispatcher* dispatcher, btBroadphaseInterface* broadphase,
    btMultiBodyConstraintSolver* solver, btCollisionConfiguration* config);

}  // namespace parksim
