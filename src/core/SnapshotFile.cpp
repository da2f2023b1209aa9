// Snapshot files (Snapshot.hpp has the format): one serializer for the whole WorldState. Each record lists its
// members once, in StateFields<Record>::each, and the same list both writes and reads them; arrays of numbers go as
// bytes, vectors with their lengths, variants with their index, everything else member by member. A read fills a
// new state and checks it whole before anyone can restore it.

#include <algorithm>
#include <array>
#include <cstring>
#include <istream>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

#include "WorldImpl.hpp"
#include "physim/core/World.hpp"

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "the snapshot format is little-endian, as this build is");

namespace physim {

// Per record: its members in file order, for writing (T const) and reading alike.
template <class T>
struct StateFields;

namespace {

constexpr char kMagic[8] = {'P', 'H', 'Y', 'S', 'N', 'A', 'P', '\0'};
constexpr std::size_t kHeaderBytes = 8 + 4 + 8 + 8 + 8;

template <class T>
struct IsVector : std::false_type {};
template <class T, class A>
struct IsVector<std::vector<T, A>> : std::true_type {};
template <class T>
struct IsStdArray : std::false_type {};
template <class T, std::size_t N>
struct IsStdArray<std::array<T, N>> : std::true_type {};
template <class T>
struct IsVariant : std::false_type {};
template <class... Ts>
struct IsVariant<std::variant<Ts...>> : std::true_type {};
template <class T>
struct IsPair : std::false_type {};
template <class A, class B>
struct IsPair<std::pair<A, B>> : std::true_type {};

template <class T>
constexpr bool kScalar = std::is_arithmetic_v<T> || std::is_enum_v<T>;

constexpr std::uint64_t kFnvBasis = 1469598103934665603ull;
constexpr std::uint64_t kFnvPrime = 1099511628211ull;

std::uint64_t fnv1a(const unsigned char* bytes, std::size_t n, std::uint64_t h = kFnvBasis) {
    for (std::size_t i = 0; i < n; ++i) {
        h ^= bytes[i];
        h *= kFnvPrime;
    }
    return h;
}

// The payload's checksum: FNV-1a's step on 8-byte words rather than bytes, in four interleaved lanes so that the
// multiplications overlap (a byte at a time takes longer than writing the file), each step followed by a shift that
// carries high bits down; the bytes past the last 32 go byte by byte, then the lanes and the length fold in. Every
// step is a bijection of its lane, so any one word changed changes the sum.
std::uint64_t payloadChecksum(const unsigned char* bytes, std::size_t n) {
    std::uint64_t lane[4] = {kFnvBasis, kFnvBasis + 1, kFnvBasis + 2, kFnvBasis + 3};
    std::size_t i = 0;
    for (; i + 32 <= n; i += 32)
        for (std::size_t k = 0; k < 4; ++k) {
            std::uint64_t word;
            std::memcpy(&word, bytes + i + 8 * k, sizeof word);
            lane[k] = (lane[k] ^ word) * kFnvPrime;
            lane[k] ^= lane[k] >> 32;
        }
    std::uint64_t h = fnv1a(bytes + i, n - i);
    for (const std::uint64_t l : lane) h = (h ^ l) * kFnvPrime;
    return (h ^ n) * kFnvPrime;
}

// Appends the state's bytes to a buffer it grows by doubling (a string's append per number costs more than the
// copies).
class Writer {
public:
    explicit Writer(std::size_t expected) : bytes_(std::max<std::size_t>(expected, 64), '\0') {}
    /// The bytes written; the writer is done.
    std::string take() {
        bytes_.resize(at_);
        return std::move(bytes_);
    }

    template <class... Ts>
    void operator()(const Ts&... values) {
        (item(values), ...);
    }
    template <class V, class F>
    void list(const V& v, F&& each) {
        count(v.size());
        for (const auto& e : v) each(e);
    }

private:
    void raw(const void* p, std::size_t n) {
        if (n == 0) return;  // an empty array's data() may be null, which memcpy must not get
        if (n > bytes_.size() - at_) bytes_.resize(std::max(2 * bytes_.size(), at_ + n));
        std::memcpy(&bytes_[at_], p, n);
        at_ += n;
    }
    void count(std::size_t n) {
        const std::uint64_t c = n;
        raw(&c, sizeof c);
    }
    template <class T>
    void item(const T& x) {
        if constexpr (kScalar<T>) {
            raw(&x, sizeof x);
        } else if constexpr (std::is_same_v<T, Vec2>) {
            item(x.x());
            item(x.y());
        } else if constexpr (IsVector<T>::value) {
            count(x.size());
            if constexpr (kScalar<typename T::value_type>) raw(x.data(), x.size() * sizeof(typename T::value_type));
            else for (const auto& e : x) item(e);
        } else if constexpr (IsStdArray<T>::value || std::is_array_v<T>) {
            for (const auto& e : x) item(e);
        } else if constexpr (IsVariant<T>::value) {
            item(static_cast<std::uint8_t>(x.index()));
            std::visit([this](const auto& alternative) { item(alternative); }, x);
        } else if constexpr (IsPair<T>::value) {
            item(x.first);
            item(x.second);
        } else {
            StateFields<T>::each(*this, x);
        }
    }

    std::string bytes_;
    std::size_t at_ = 0;
};

// Takes the state's bytes back; running past the end throws (the file's length and checksum agreed, so that is a
// payload this build does not read as it was written).
class Reader {
public:
    Reader(const unsigned char* begin, const unsigned char* end) : at_(begin), end_(end) {}

    template <class... Ts>
    void operator()(Ts&... values) {
        (item(values), ...);
    }
    template <class V, class F>
    void list(V& v, F&& each) {
        v.resize(count(1));
        for (auto& e : v) each(e);
    }
    std::size_t left() const { return static_cast<std::size_t>(end_ - at_); }

private:
    void raw(void* p, std::size_t n) {
        if (n == 0) return;  // an empty array's data() may be null, which memcpy must not get
        if (n > left()) throw std::runtime_error("the payload ends before its state does (not written by this format)");
        std::memcpy(p, at_, n);
        at_ += n;
    }
    // A length, checked against the bytes left (each element takes at least `least`), so no bad length allocates.
    std::size_t count(std::size_t least) {
        std::uint64_t c = 0;
        raw(&c, sizeof c);
        if (c > left() / least)
            throw std::runtime_error("the payload holds an array of " + std::to_string(c) +
                                     " elements, more than its " + std::to_string(left()) + " bytes left");
        return static_cast<std::size_t>(c);
    }
    template <class V, std::size_t... I>
    static void emplaceIndex(V& v, std::size_t index, std::index_sequence<I...>) {
        ((index == I ? (void)v.template emplace<I>() : (void)0), ...);
    }
    template <class T>
    void item(T& x) {
        if constexpr (std::is_same_v<T, bool>) {
            std::uint8_t b = 0;
            raw(&b, 1);
            x = b != 0;
        } else if constexpr (kScalar<T>) {
            raw(&x, sizeof x);
        } else if constexpr (std::is_same_v<T, Vec2>) {
            item(x.x());
            item(x.y());
        } else if constexpr (IsVector<T>::value) {
            using E = typename T::value_type;
            x.resize(count(kScalar<E> ? sizeof(E) : 1));
            if constexpr (kScalar<E> && !std::is_same_v<E, bool>) raw(x.data(), x.size() * sizeof(E));
            else for (auto& e : x) item(e);
        } else if constexpr (IsStdArray<T>::value || std::is_array_v<T>) {
            for (auto& e : x) item(e);
        } else if constexpr (IsVariant<T>::value) {
            std::uint8_t index = 0;
            item(index);
            if (index >= std::variant_size_v<T>)
                throw std::runtime_error("the payload names kind " + std::to_string(index) + " of " +
                                         std::to_string(std::variant_size_v<T>));
            emplaceIndex(x, index, std::make_index_sequence<std::variant_size_v<T>>{});
            std::visit([this](auto& alternative) { item(alternative); }, x);
        } else if constexpr (IsPair<T>::value) {
            item(x.first);
            item(x.second);
        } else {
            StateFields<T>::each(*this, x);
        }
    }

    const unsigned char* at_;
    const unsigned char* end_;
};

}  // namespace

// --- the records' members, in file order: a member added to a record is added here (the sizes below remind) ----

#define PHYSIM_FIELDS(Record, ...)                      \
    template <>                                          \
    struct StateFields<Record> {                         \
        template <class Io, class R>                     \
        static void each(Io& io, R& r) { io(__VA_ARGS__); } \
    }

PHYSIM_FIELDS(Rotation, r.c, r.s);
PHYSIM_FIELDS(Transform, r.p, r.q);
PHYSIM_FIELDS(Aabb, r.lower, r.upper);
PHYSIM_FIELDS(MassProperties, r.area, r.centroid, r.secondMoment);
PHYSIM_FIELDS(Filter, r.categoryBits, r.maskBits, r.groupIndex);
PHYSIM_FIELDS(BodyId, r.index, r.generation);
PHYSIM_FIELDS(ShapeId, r.index, r.generation);
PHYSIM_FIELDS(JointId, r.index, r.generation);
PHYSIM_FIELDS(Circle, r.center, r.radius);
PHYSIM_FIELDS(Segment, r.point1, r.point2);
PHYSIM_FIELDS(Capsule, r.center1, r.center2, r.radius);
PHYSIM_FIELDS(ChainSegment, r.ghost1, r.segment, r.ghost2);
PHYSIM_FIELDS(WorldSettings, r.gravity, r.substeps, r.velocityIterations, r.relaxIterations, r.contactHertz,
              r.contactDampingRatio, r.contactPushMaxVelocity, r.jointHertz, r.jointDampingRatio, r.jointArcs,
              r.directChainMassRatio, r.linearSlop, r.restitutionThreshold, r.impactSpeedThreshold, r.enableSleep,
              r.sleepLinearTolerance, r.sleepAngularTolerance, r.timeToSleep, r.threads, r.frictionMixing,
              r.restitutionMixing);
PHYSIM_FIELDS(BodyData, r.xf, r.center, r.angle, r.v, r.w, r.extent, r.detection, r.type, r.awakeIndex, r.collides,
              r.force, r.torque, r.turnReach, r.localCenter, r.mass, r.invMass, r.inertia, r.invInertia, r.density,
              r.unitMass, r.shapeHead, r.shapeTail, r.shapeCount, r.coreRadius, r.precision, r.useGravity, r.gravityScale,
              r.attracting, r.fixedRotation, r.allowSleep, r.alive, r.generation, r.aabb, r.contactHead,
              r.contactCount, r.jointHead, r.island, r.islandPrev, r.islandNext, r.sleepTime);
PHYSIM_FIELDS(ShapeData, r.body, r.proxy, r.aabb, r.geometry, r.density, r.restitution, r.staticFriction,
              r.dynamicFriction, r.unitMass, r.filter, r.sensor, r.rollingResistance, r.tangentSpeed, r.next,
              r.generation, r.alive);
PHYSIM_FIELDS(ContactPoint, r.point, r.separation, r.normalImpulse, r.tangentImpulse, r.id);
PHYSIM_FIELDS(Manifold, r.bodyA, r.bodyB, r.shapeA, r.shapeB, r.normal, r.pointCount, r.points);
PHYSIM_FIELDS(ManifoldCache::Point, r.onA, r.onB, r.id, r.rounding);
PHYSIM_FIELDS(ManifoldCache, r.margin, r.pointCount, r.quietAtAnyMargin, r.quietArm, r.offset, r.angle, r.quiet,
              r.normal, r.points);
PHYSIM_FIELDS(ContactMaterial, r.staticFriction, r.dynamicFriction, r.restitution);
PHYSIM_FIELDS(ContactData, r.material, r.sliding, r.keepsPush, r.touching, r.alive, r.awakeIndex, r.manifold,
              r.cache, r.prev, r.next, r.generation, r.proxyA, r.proxyB, r.disabled);
PHYSIM_FIELDS(ContactSurface, r.rolling, r.tangentSpeed);
PHYSIM_FIELDS(StepImpulses, r.normal, r.tangent);
PHYSIM_FIELDS(ContactCores, r.radiusA, r.radiusB, r.facesA, r.facesB);
PHYSIM_FIELDS(DistanceJoint, r.length, r.hertz, r.dampingRatio, r.impulse);
PHYSIM_FIELDS(MouseJoint, r.maxForce, r.hertz, r.dampingRatio, r.linearImpulse);
PHYSIM_FIELDS(SpringJoint, r.restLength, r.stiffness, r.damping);
PHYSIM_FIELDS(RevoluteJoint, r.referenceAngle, r.enableLimit, r.enableMotor, r.enableSpring, r.lowerAngle,
              r.upperAngle, r.motorSpeed, r.maxMotorTorque, r.springHertz, r.springDampingRatio,
              r.springTargetAngle, r.linearImpulse, r.motorImpulse, r.lowerImpulse, r.upperImpulse, r.springImpulse);
PHYSIM_FIELDS(WeldJoint, r.referenceAngle, r.linearImpulse, r.angularImpulse);
PHYSIM_FIELDS(PulleyJoint, r.groundA, r.groundB, r.ratio, r.length, r.impulse);
PHYSIM_FIELDS(MotorJoint, r.angularOffset, r.maxForce, r.maxTorque, r.correctionFactor, r.linearImpulse,
              r.angularImpulse);
PHYSIM_FIELDS(PrismaticJoint, r.localAxis, r.referenceAngle, r.enableLimit, r.enableMotor, r.enableSpring,
              r.lowerTranslation, r.upperTranslation, r.motorSpeed, r.maxMotorForce, r.hertz, r.dampingRatio,
              r.targetTranslation, r.blockImpulse, r.springImpulse, r.motorImpulse, r.lowerImpulse, r.upperImpulse,
              r.lastAxis);
PHYSIM_FIELDS(WheelJoint, r.localAxis, r.enableSpring, r.enableLimit, r.enableMotor, r.hertz, r.dampingRatio,
              r.lowerTranslation, r.upperTranslation, r.motorSpeed, r.maxMotorTorque, r.normalImpulse,
              r.springImpulse, r.lowerImpulse, r.upperImpulse, r.motorImpulse, r.lastAxis);
PHYSIM_FIELDS(GearJoint, r.joint1, r.joint2, r.ratio, r.angularA, r.angularB, r.linearA, r.linearB, r.initial,
              r.impulse);
PHYSIM_FIELDS(JointData, r.params, r.a, r.b, r.toWorld, r.localA, r.localB, r.prev, r.next, r.generation, r.alive,
              r.collideConnected, r.breakForce, r.breakTorque);
PHYSIM_FIELDS(JointBreakEvent, r.joint, r.bodyA, r.bodyB, r.force, r.torque);
PHYSIM_FIELDS(JointEvents, r.broken);
PHYSIM_FIELDS(IslandData, r.head, r.tail, r.bodyCount, r.constraintRemoveCount, r.generation, r.awake, r.alive);
PHYSIM_FIELDS(ContactEvent, r.bodyA, r.bodyB, r.shapeA, r.shapeB);
PHYSIM_FIELDS(ImpactEvent, r.bodyA, r.bodyB, r.shapeA, r.shapeB, r.point, r.normal, r.approachSpeed);
PHYSIM_FIELDS(ContactEvents, r.begin, r.end, r.impacts);
PHYSIM_FIELDS(SensorEvent, r.sensorShape, r.visitorShape, r.sensorBody, r.visitorBody, r.fraction, r.time);
PHYSIM_FIELDS(SensorEvents, r.begin, r.end);
PHYSIM_FIELDS(SensorStage::Visitor, r.shape, r.generation);
PHYSIM_FIELDS(DragDef, r.linear, r.dragCoefficient, r.fluidDensity, r.width, r.angular);
PHYSIM_FIELDS(GravitationSettings, r.G, r.softening, r.theta, r.directBelow);
PHYSIM_FIELDS(DynamicTree::Node, r.box, r.parent, r.child1, r.child2, r.height, r.userData);
// The classes' scratch (a tree's insertion heap and rebuild lists, the broad phase's per-task pair lists and its
// wide query tree) is rebuilt when used, so it stays out.
PHYSIM_FIELDS(DynamicTree, r.nodes_, r.root_, r.freeList_, r.proxyCount_);
PHYSIM_FIELDS(PairSet, r.slots_, r.mask_, r.count_, r.tombstones_);
PHYSIM_FIELDS(BroadPhase, r.tree_, r.moved_, r.boxRevision_, r.isMoved_);
PHYSIM_FIELDS(Members, r.items_, r.position_);
PHYSIM_FIELDS(GravitationEffect, r.members_, r.settings_);
PHYSIM_FIELDS(SpringEffect, r.members_);
// The user's force callbacks stay out (std::function): a restore from a file keeps the receiving world's.
PHYSIM_FIELDS(Effects, r.gravitation, r.springs, r.drag);
// The Continuous stage keeps only its last count: its batch, sweeps and shape table are the run's scratch (the
// table is built again for a state read back, whose stage starts with no table).
PHYSIM_FIELDS(ContinuousStage, r.impacts_);

#undef PHYSIM_FIELDS

// A polygon's vertices and normals up to its count: the rest were never set (Eigen leaves them as they were) and are
// read back as zeros.
template <>
struct StateFields<Polygon> {
    static void each(Writer& io, const Polygon& r) {
        io(r.count, r.radius);
        for (std::size_t i = 0; i < static_cast<std::size_t>(r.count); ++i) io(r.vertices[i], r.normals[i]);
    }
    static void each(Reader& io, Polygon& r) {
        io(r.count, r.radius);
        if (r.count < 0 || r.count > Polygon::maxVertices)
            throw std::runtime_error("the payload holds a polygon of " + std::to_string(r.count) + " vertices");
        for (std::size_t i = 0; i < r.vertices.size(); ++i) {
            r.vertices[i] = r.normals[i] = Vec2::Zero();
            if (i < static_cast<std::size_t>(r.count)) io(r.vertices[i], r.normals[i]);
        }
    }
};

template <>
struct StateFields<DragEffect> {
    template <class Io, class R>
    static void each(Io& io, R& r) {
        io(r.members_, r.defs_);
        io.list(r.coefficients_, [&io](auto& c) { io(c.linear, c.quadratic, c.angular); });
    }
};

// Its overlaps and the paths' starts; the run's movers, candidates and next overlaps are its scratch.
template <>
struct StateFields<SensorStage> {
    template <class Io, class R>
    static void each(Io& io, R& r) {
        io.list(r.sensors_, [&io](auto& s) { io(s.shape, s.overlaps); });
        io.list(r.starts_, [&io](auto& s) { io(s.center, s.v, s.angle, s.w, s.step); });
        io(r.events_);
    }
};

// Every member but the solver (its rows' layout and scratch: a restore marks the layout stale, as World::restore
// does), the pair filter and pre-solve hook (std::function: the receiving world's stay), the profile (timings),
// contacts()' cache and the stepping flag.
template <>
struct StateFields<WorldState> {
    template <class Io, class R>
    static void each(Io& io, R& r) {
        io(r.settings, r.bodies, r.freeBodies, r.liveCount, r.dynamicCount, r.continuousCount, r.shapeRevision,
           r.awake, r.shapes, r.freeShapes, r.shapeLiveCount, r.contacts, r.freeContacts, r.awakeContacts,
           r.awakeHasPoints,
           r.contactPairs, r.contactSurfaces, r.contactCores, r.contactImpulses, r.joints, r.freeJoints, r.jointCount, r.rowJointCount,
           r.breakableJoints, r.jointEvents, r.islands, r.freeIslands, r.broadPhase, r.continuous, r.effects,
           r.sensors, r.newPairs, r.contactFlags, r.changedContacts, r.awakeContactsChanged, r.checkedBoxRevision,
           r.touched, r.islandSleep, r.splitStack, r.splitMembers, r.found, r.sleepy, r.refiltered, r.refilterAll,
           r.events, r.dt, r.stepCount, r.surfaceMaterials);
    }
};

namespace {

// The records the serializer lists member by member, with their sizes on this build: one that gains a member
// changes its size (most often), and this fails to compile until its StateFields list (and kFormatVersion) follow.
template <class... Records>
struct RecordList {
    static std::uint64_t fingerprint() {
        const std::uint64_t sizes[] = {sizeof(Records)..., alignof(Records)...};
        return fnv1a(reinterpret_cast<const unsigned char*>(sizes), sizeof sizes);
    }
};
using Records = RecordList<BodyData, ShapeData, ContactData, ManifoldCache, Manifold, ContactPoint, JointData,
                           JointKinds::Params, DistanceJoint, MouseJoint, SpringJoint, RevoluteJoint, WeldJoint,
                           PulleyJoint, MotorJoint, PrismaticJoint, WheelJoint, GearJoint, IslandData, Geometry,
                           Polygon, Circle, Segment, Capsule, ChainSegment, WorldSettings, DynamicTree::Node,
                           ContactSurface, ContactCores, StepImpulses, JointBreakEvent, ImpactEvent, SensorEvent, DragDef,
                           GravitationSettings, Filter, Vec2, std::size_t, int, bool>;

#if defined(__x86_64__) && defined(__LP64__)
template <class T, std::size_t Expected, std::size_t Size = sizeof(T)>
constexpr bool sizeIs() {
    static_assert(Size == Expected, "a record's size changed: update its StateFields list and kFormatVersion");
    return true;
}
static_assert(sizeIs<BodyData, 384>() && sizeIs<ShapeData, 480>() && sizeIs<ContactData, 384>() &&
              sizeIs<ManifoldCache, 160>() && sizeIs<Manifold, 160>() && sizeIs<JointData, 272>() &&
              sizeIs<DistanceJoint, 32>() && sizeIs<MouseJoint, 48>() && sizeIs<SpringJoint, 24>() &&
              sizeIs<RevoluteJoint, 128>() && sizeIs<WeldJoint, 48>() && sizeIs<PulleyJoint, 64>() &&
              sizeIs<MotorJoint, 64>() && sizeIs<PrismaticJoint, 160>() && sizeIs<WheelJoint, 128>() &&
              sizeIs<GearJoint, 96>() && sizeIs<IslandData, 24>() && sizeIs<WorldSettings, 160>() &&
              sizeIs<DynamicTree::Node, 64>() && sizeIs<GravitationSettings, 32>() && sizeIs<DragDef, 40>() &&
              sizeIs<SensorEvent, 48>() && sizeIs<ImpactEvent, 80>() && sizeIs<JointBreakEvent, 64>());
#endif

std::uint64_t layoutFingerprint() { return Records::fingerprint(); }

std::string hex(std::uint64_t v) {
    static const char digits[] = "0123456789abcdef";
    std::string s(16, '0');
    for (int i = 15; i >= 0; --i, v >>= 4) s[static_cast<std::size_t>(i)] = digits[v & 15];
    return s;
}

template <class T>
void put(std::string& out, T value) {
    out.append(reinterpret_cast<const char*>(&value), sizeof value);
}
template <class T>
T take(const unsigned char*& at) {
    T value;
    std::memcpy(&value, at, sizeof value);
    at += sizeof value;
    return value;
}

[[noreturn]] void refuse(const std::string& why) { throw std::runtime_error("physim: snapshot file: " + why); }

}  // namespace

void WorldSnapshot::write(std::ostream& out) const {
    if (empty()) throw std::invalid_argument("physim: WorldSnapshot::write: the snapshot is empty");
    Writer w(bytes());
    w(*state_, stateHash_);
    const std::string payload = w.take();
    std::string header(kMagic, sizeof kMagic);
    put(header, kFormatVersion);
    put(header, layoutFingerprint());
    put(header, static_cast<std::uint64_t>(payload.size()));
    put(header, payloadChecksum(reinterpret_cast<const unsigned char*>(payload.data()), payload.size()));
    out.write(header.data(), static_cast<std::streamsize>(header.size()));
    out.write(payload.data(), static_cast<std::streamsize>(payload.size()));
    out.flush();
    if (!out) throw std::runtime_error("physim: WorldSnapshot::write: the stream failed");
}

WorldSnapshot WorldSnapshot::read(std::istream& in) {
    unsigned char header[kHeaderBytes];
    in.read(reinterpret_cast<char*>(header), sizeof header);
    const std::size_t got = static_cast<std::size_t>(in.gcount());
    if (got >= sizeof kMagic && std::memcmp(header, kMagic, sizeof kMagic) != 0)
        refuse("not a physim snapshot (wrong magic)");
    if (got < sizeof header)
        refuse("truncated: its header is " + std::to_string(got) + " of " + std::to_string(sizeof header) + " bytes");
    const unsigned char* at = header + sizeof kMagic;
    const auto version = take<std::uint32_t>(at);
    if (version != kFormatVersion)
        refuse("format version " + std::to_string(version) + ", this build reads version " +
               std::to_string(kFormatVersion));
    const auto fingerprint = take<std::uint64_t>(at);
    if (fingerprint != layoutFingerprint())
        refuse("layout fingerprint " + hex(fingerprint) + " differs from this build's " + hex(layoutFingerprint()) +
               " (written by a build whose records differ)");
    const auto length = take<std::uint64_t>(at);
    const auto checksum = take<std::uint64_t>(at);

    // The payload, read in chunks so a length the stream does not hold fails as truncated, not as an allocation.
    std::string payload;
    constexpr std::size_t kChunk = std::size_t{1} << 20;
    while (payload.size() < length) {
        const std::size_t want = static_cast<std::size_t>(std::min<std::uint64_t>(kChunk, length - payload.size()));
        const std::size_t before = payload.size();
        payload.resize(before + want);
        in.read(&payload[before], static_cast<std::streamsize>(want));
        const std::size_t read = static_cast<std::size_t>(in.gcount());
        if (read < want)
            refuse("truncated: its payload is " + std::to_string(before + read) + " of " + std::to_string(length) +
                   " bytes");
    }
    const auto* begin = reinterpret_cast<const unsigned char*>(payload.data());
    const std::uint64_t sum = payloadChecksum(begin, payload.size());
    if (sum != checksum)
        refuse("corrupt: its payload's checksum is " + hex(sum) + ", its header says " + hex(checksum));

    auto state = std::make_shared<WorldState>();
    std::uint64_t recordedHash = 0;
    Reader r(begin, begin + payload.size());
    try {
        r(*state, recordedHash);
    } catch (const std::runtime_error& e) {
        refuse(e.what());
    }
    if (r.left() != 0) refuse(std::to_string(r.left()) + " bytes follow the state (not written by this format)");
    const std::uint64_t hash = stateHashOf(*state);
    if (hash != recordedHash)
        refuse("the state read back hashes to " + hex(hash) + ", the file recorded " + hex(recordedHash));
    WorldSnapshot s;
    s.state_ = std::move(state);
    s.stateHash_ = hash;
    s.fromFile_ = true;
    return s;
}

}  // namespace physim
