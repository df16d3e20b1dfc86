// grape for JavaScript: types of the WebAssembly module (web/src/bind_*.cpp).
// Objects made by the module (Path, Curve, Engine, Animation, ...) hold WebAssembly memory:
// call .delete() when done with one. Errors are thrown as Error with grape's message.
// Typed-array views (Engine.positions, ParticleSystem.positions, ...) point into the module's
// memory: take a new view after anything that may allocate (adding animations or particles),
// since growing memory detaches the old ones (their length becomes 0).

export interface Vec2 { x: number; y: number; }
/** The nearest point of a path: its parameter, the point, the distance (world units). */
export interface ClosestPoint { u: number; point: Vec2; distance: number; }
/** A path's frame at u: point, unit tangent, unit normal, curvature (1 / world units). */
export interface PathFrame { point: Vec2; tangent: Vec2; normal: Vec2; curvature: number; }
export interface Bounds { min: Vec2; max: Vec2; }

interface Deletable { delete(): void; }

/** Path kinds as Path.kind() names them. */
export type PathKind = 'linear' | 'circle' | 'elliptical_arc' | 'spiral' | 'sine_wave' | 'quadratic_bezier' |
  'cubic_bezier' | 'linear_spline' | 'cosine_spline' | 'hermite_spline' | 'catmull_rom_spline' | 'physics' |
  'complex' | 'reparametrized';

/** Flat x, y pairs. */
export type Points = ArrayLike<number>;

/** A 2-D path: u in [0, 1] to a point; extends along its end tangents outside [0, 1]. */
export interface Path extends Deletable {
  /** Position at parameter u. */
  point(u: number): Vec2;
  /** dx/du (analytic). */
  d1(u: number): Vec2;
  /** d²x/du² (analytic). */
  d2(u: number): Vec2;
  /** atan2(d1.y, d1.x), radians. */
  heading(u: number): number;
  /** Arc length over [0, 1]. */
  length(): number;
  /** Arc length from 0 to u. */
  lengthAt(u: number): number;
  /** The u where lengthAt(u) == s. */
  uAtLength(s: number): number;
  bounds(): Bounds;
  /** A polyline within `tolerance` of the path, as x, y pairs. */
  flatten(tolerance: number): Float64Array;
  /** point(u) for each u, as x, y pairs (one call for many samples). */
  sample(us: ArrayLike<number>): Float64Array;
  /** The same shape at constant speed (arc length within 1e-9 of exact). */
  reparametrized(): Path;
  /** The globally nearest point to (x, y), within 1e-12 of the path's size; ties go to the
   *  smallest u. With u0, u1: the nearest within that range of u. */
  closestPoint(x: number, y: number, u0?: number, u1?: number): ClosestPoint;
  /** The nearest point to a moving (x, y), starting from the last answer's u. */
  closestPointFrom(x: number, y: number, lastU: number): ClosestPoint;
  /** Unit tangent, normal and signed curvature at u. */
  frame(u: number): PathFrame;
  kind(): PathKind;
  /** The same shape object. */
  same(other: Path): boolean;
}

export interface ComplexPath extends Path {
  /** The parts as given (skipped ones included). */
  partCount(): number;
  part(i: number): Path;
  cues(): Float64Array;
}

export interface PathStatic {
  new(): Path;
  linear(start: Vec2, end: Vec2): Path;
  circle(center: Vec2, radius: number, startAngle: number, endAngle: number): Path;
  ellipticalArc(center: Vec2, rx: number, ry: number, rotation: number, startAngle: number, endAngle: number): Path;
  spiral(center: Vec2, startRadius: number, endRadius: number, startAngle: number, endAngle: number): Path;
  sineWave(start: Vec2, end: Vec2, frequency: number, amplitude: number): Path;
  quadraticBezier(p0: Vec2, p1: Vec2, p2: Vec2, reparametrize: boolean): Path;
  cubicBezier(p0: Vec2, p1: Vec2, p2: Vec2, p3: Vec2, reparametrize: boolean): Path;
  linearSpline(xy: Points): Path;
  cosineSpline(xy: Points): Path;
  hermiteSpline(xy: Points, tangents: Points): Path;
  catmullRom(xy: Points, type: 'uniform' | 'centripetal' | 'chordal'): Path;
  /** position + velocity·t + ½·acceleration·t², t = u·seconds. */
  physics(position: Vec2, velocity: Vec2, acceleration: Vec2, seconds: number): Path;
  /** Part i spans u in [cues[i], cues[i+1]). */
  complex(parts: Path[], cues: ArrayLike<number>): ComplexPath;
  complexByLength(parts: Path[]): ComplexPath;
  /** SVG path data (y down). */
  svg(data: string): ComplexPath;
}

/** An easing curve: progress at normalized time t. */
export interface Curve extends Deletable {
  at(t: number): number;
  atMany(ts: ArrayLike<number>): Float64Array;
  /** The name parse reads back ("quad-in-out", "back-out(2.5)", "cubic-bezier(...)"). */
  name(): string;
  kind(): string;
  equals(other: Curve): boolean;
  /** A spring's span in seconds of spring time (0 for other kinds). */
  settlingTime(): number;
}
export interface CurveStatic {
  new(): Curve;
  /** Any parse_curve name; an unknown one throws, listing the valid names. */
  parse(name: string): Curve;
  /** y at x along SVG path data from x = 0 to x = 1 (GSAP's CustomEase data). */
  svg(data: string): Curve;
  /** A damped spring; velocity in progress per second (parse("spring(170,26)") takes mass 1, velocity 0). */
  spring(stiffness: number, damping: number, mass: number, velocity: number): Curve;
  /** A spring by perceptual duration and bounce in (−1, 1), as SwiftUI gives it. */
  springDuration(duration: number, bounce: number, velocity: number): Curve;
}

/** How an animation plays (all optional). */
export interface AnimationOptions {
  /** A curve name or a Curve (default linear). */
  curve?: string | Curve;
  /** Seconds before the first play. */
  delay?: number;
  /** Extra plays: 0 once, −1 forever. */
  repeat?: number;
  reversed?: boolean;
  /** Every second play runs backwards. */
  yoyo?: boolean;
  timeScale?: number;
  paused?: boolean;
  /** Also track the heading (written to target.rotation by Engine.animate). */
  heading?: boolean;
  /** The path's u where each play starts and ends, in [0, 1] (default 0 and 1; end < start runs back). */
  rangeStart?: number;
  rangeEnd?: number;
  /** Sideways distance from the path towards its normal, world units (a lane beside a track). */
  offset?: number;
}

/** A generation-checked handle: inert once its animation completed or was killed. */
export interface Animation extends Deletable {
  alive(): boolean;
  waiting(): boolean;
  paused(): boolean;
  value(): Vec2;
  /** A 3-D animation's position (offsets included); {0, 0, 0} for others. */
  value3(): Vec3;
  heading(): number;
  progress(): number;
  time(): number;
  repetition(): number;
  duration(): number;
  timeScale(): number;
  pause(): void;
  resume(): void;
  seek(seconds: number): void;
  setTimeScale(scale: number): void;
  kill(): void;
  onComplete(handler: () => void): void;
  onLoop(handler: (play: number) => void): void;
}

/** The animation engine with `capacity` position slots (fixed at construction). */
export interface Engine extends Deletable {
  /** A new animation writing x, y into slot k = the returned index: positions()[2k], [2k + 1]. */
  add(path: Path, duration: number, options?: AnimationOptions): number;
  /** The handle of slot k's animation. */
  animation(slot: number): Animation;
  /** An animation writing target.x, target.y (and target.rotation with heading) on each change. */
  animate(target: { x: number; y: number; rotation?: number }, path: Path, duration: number,
          options?: AnimationOptions): Animation;
  /** An animation reporting (x, y, heading) to a callback on each change. */
  onUpdate(path: Path, duration: number, options: AnimationOptions,
           callback: (x: number, y: number, heading: number) => void): Animation;
  /** Advances every animation by dt seconds. */
  tick(dt: number): void;
  /** x, y of every used slot, one view over the engine's memory (2·used() numbers). */
  positions(): Float64Array;
  used(): number;
  capacity(): number;
  /** Live animations. */
  size(): number;
  storageBytes(): number;
  /** Kills every animation and frees every slot. */
  clear(): void;
  onTick(listener: (dt: number) => void): number;
  removeTickListener(id: number): void;
  /** A 3-D animation writing slot k = the returned index of positions3(): x, y, z at [7k, 7k + 2],
   *  the orientation w, x, y, z at [7k + 3, 7k + 6]. `timing` is seconds per play or {speed}
   *  (constant speed in units per second: plays the path reparametrized, length / speed per play);
   *  the options' heading and offset are 2-D only and refused. */
  add3(path: Path3, timing: number | { speed: number }, options?: AnimationOptions, motion?: Motion3Options): number;
  /** The handle of 3-D slot k's animation (its value3() is the slot's position). */
  animation3(slot: number): Animation;
  /** x, y, z, w, qx, qy, qz of every used 3-D slot (7·used3() numbers, a view: see the note at the top). */
  positions3(): Float64Array;
  used3(): number;
  capacity3(): number;
}
export interface EngineStatic {
  /** `capacity` 2-D slots and `capacity3` 3-D slots (default 0), fixed. */
  new(capacity: number, capacity3?: number): Engine;
  bytesPerAnimation(): number;
}

export type IntegratorName = 'euler' | 'semi_implicit_euler' | 'symplectic' | 'midpoint' | 'rk4' | 'velocity_verlet' |
  'verlet' | 'rk45';
export type DriftName = 'none' | 'baumgarte' | 'projection';

export interface DriftOptions {
  drift?: DriftName;
  omegaDt?: number;
  stiffness?: number;
  damping?: number;
  projectionIterations?: number;
  projectionTolerance?: number;
}
export interface ParticleSystemOptions extends DriftOptions {
  integrator?: IntegratorName;
  solver?: 'automatic' | 'dense' | 'sparse_direct' | 'conjugate_gradient';
  rk45Tolerance?: number;
}
export interface StepStats {
  status: 'ok' | 'singular' | 'not_converged';
  evaluations: number; substeps: number; rejected: number; projectionIterations: number; cgIterations: number;
}
export interface ConstraintResidual { value: number; rate: number; distance: number; }

/** Particles, forces and constraints (Witkin's solver at every integrator stage). */
export interface ParticleSystem extends Deletable {
  /** Returns the particle's index; mass Infinity pins it. */
  addParticle(position: Vec2, velocity: Vec2, mass: number): number;
  size(): number;
  /** x, y per particle (a view: see the note at the top). */
  positions(): Float64Array;
  velocities(): Float64Array;
  inverseMasses(): Float64Array;
  position(i: number): Vec2;
  velocity(i: number): Vec2;
  mass(i: number): number;
  setPosition(i: number, p: Vec2): void;
  setVelocity(i: number, v: Vec2): void;
  /** A force held for the next step. */
  exertForce(i: number, f: Vec2): void;
  addGravity(g: Vec2): void;
  addDrag(k: number): void;
  addSpring(a: number, b: number, restLength: number, stiffness: number, damping: number): void;
  /** |xa − xb| = length (held at the current distance when length is undefined). */
  addDistance(a: number, b: number, length?: number): number;
  addAnchor(a: number, anchor: Vec2, length: number): number;
  addFixedPoint(a: number, point: Vec2): number;
  /** C = a·x² + b·x·y + c·y² + d·x + e·y + f = 0 ([1, 0, 0, 0, 100, 0]: the seed's parabola). */
  addConic(a: number, coefficients: ArrayLike<number>): number;
  /** C(x, y) = 0 from a function giving C, its gradient and Hessian. */
  addCurve(a: number, c: (x: number, y: number) =>
    { value: number; gx: number; gy: number; hxx: number; hxy: number; hyy: number }): number;
  constraintCount(): number;
  setDrift(options: DriftOptions): void;
  setIntegrator(name: IntegratorName): void;
  step(dt: number): StepStats;
  /** n steps of dt, no report. */
  steps(dt: number, n: number): void;
  time(): number;
  kineticEnergy(): number;
  potentialEnergy(): number;
  energy(): number;
  maxResidual(): ConstraintResidual;
  residuals(): ConstraintResidual[];
}
export interface ParticleSystemStatic { new(options?: ParticleSystemOptions): ParticleSystem; }

export interface BeadOptions {
  u?: number; speed?: number; mass?: number; gravity?: Vec2; drag?: number;
  ends?: 'stop' | 'bounce'; restitution?: number; integrator?: IntegratorName;
}
/** A bead sliding on any path in its generalized coordinate (joins of a ComplexPath kept). */
export interface Bead extends Deletable {
  /** An extra force; null removes it. */
  setForce(force: ((t: number, x: number, y: number, vx: number, vy: number) => Vec2) | null): void;
  step(dt: number): void;
  time(): number; u(): number; uRate(): number; position(): Vec2; velocity(): Vec2; speed(): number;
  energy(): number; acceleration(): number; crossings(): number;
}
export interface BeadStatic { new(path: Path, options?: BeadOptions): Bead; }

export interface ParabolaOptions {
  method?: 'implicit' | 'parametric' | 'seed';
  integrator?: IntegratorName;
  x0?: number; g?: number; mass?: number; forceX?: number;
  stabilize?: DriftName; omegaDt?: number;
}
export interface ParabolaState { t: number; x: number; y: number; vx: number; vy: number; residual: number; distance: number; energy: number; }
/** The seed's bead on x² + 100y = 0, by the code of `grape simulate parabola`. */
export interface ParabolaRun extends Deletable { step(dt: number): void; state(): ParabolaState; }
export interface ParabolaRunStatic { new(options?: ParabolaOptions): ParabolaRun; }
/** The fields `grape simulate parabola` prints, plus max_energy_error. */
export interface ParabolaSummary {
  method: string; integrator: string; stabilize: string; dt: number; seconds: number;
  x: number; y: number; vx: number; vy: number; max_residual: number; max_distance: number;
  initial_energy: number; final_energy: number; max_energy_error: number;
}

export interface BitVector extends Deletable {
  size(): number;
  /** Checked: an index ≥ size() throws. */
  get(i: number): boolean;
  set(i: number, value: boolean): void;
  flip(i: number): void;
  testAndSet(i: number): boolean;
  setAll(): void; clearAll(): void; flipAll(): void;
  andWith(o: BitVector): void; orWith(o: BitVector): void; xorWith(o: BitVector): void; subtract(o: BitVector): void;
  and(o: BitVector): BitVector; or(o: BitVector): BitVector; xor(o: BitVector): BitVector; not(): BitVector;
  count(): number; any(): boolean; none(): boolean; all(): boolean;
  isSubsetOf(o: BitVector): boolean; intersects(o: BitVector): boolean;
  /** −1 when there is none. */
  findFirst(): number;
  findNext(i: number): number;
  setBits(): number[];
  resize(size: number, value: boolean): void;
  equals(o: BitVector): boolean;
  /** "0101", bit 0 first. */
  toString(): string;
  clone(): BitVector;
}
export interface BitVectorStatic { new(size: number, value: boolean): BitVector; fromString(bits: string): BitVector; }

export interface PairBits extends Deletable {
  test(i: number, j: number): boolean; set(i: number, j: number, value: boolean): void;
  testAndSet(i: number, j: number): boolean; index(i: number, j: number): number; pairCount(): number; clearAll(): void;
}
export interface PairBitsStatic { new(objectCount: number): PairBits; }

export interface KeyState extends Deletable {
  press(key: number): void; release(key: number): void; releaseAll(): void;
  isDown(key: number): boolean; pressedThisFrame(key: number): boolean; releasedThisFrame(key: number): boolean;
  /** Ends the frame; with dt (seconds) also gathers the key repeats due (KeyRepeatDef). */
  endFrame(dt?: number): void;
  mask(keys: ArrayLike<number>): BitVector;
  allDown(mask: BitVector): boolean; anyDown(mask: BitVector): boolean;
  down(): BitVector; keyCount(): number;
}
export interface KeyStateStatic { new(keyCount: number): KeyState; }

export interface SpritePlayerOptions { rate?: number; mode?: 'loop' | 'once' | 'ping_pong'; startFrame?: number; }
/** Plays frame numbers at any real rate (the remainder carries the fraction). */
export interface SpritePlayer extends Deletable {
  advance(): void;
  advanceBy(dt: number, fps: number): void;
  frame(): number; remainder(): number; rate(): number; setRate(rate: number): void;
  mode(): string; setMode(mode: 'loop' | 'once' | 'ping_pong'): void;
  frameCount(): number; setFrame(k: number): void;
  playing(): boolean; pause(): void; play(): void;
  onFrame(f: (frame: number) => void): void; onComplete(f: () => void): void; onLoop(f: (cycle: number) => void): void;
}
export interface SpritePlayerStatic { new(frameCount: number, options?: SpritePlayerOptions): SpritePlayer; }

export interface FrameRect { x: number; y: number; width: number; height: number; }
export interface TileSheetOptions {
  width: number; height: number; columns?: number; rows?: number; margin?: number; spacing?: number;
  frameWidth?: number; frameHeight?: number; frameCount?: number;
}
export interface TileSheet extends Deletable { width(): number; height(): number; frameCount(): number; frame(k: number): FrameRect; }
export interface TileSheetStatic { new(options: TileSheetOptions): TileSheet; }

// ---- 3-D (web/src/bind_3d.cpp) ------------------------------------------------------------

/** A 3-D point or vector in world units (right-handed, z up for View3). */
export interface Vec3 { x: number; y: number; z: number; }
/** A quaternion w + xi + yj + zk; as an orientation a unit one, q and −q the same rotation. */
export interface Quat { w: number; x: number; y: number; z: number; }
/** Where a rotation takes the world axes (the columns of its matrix). */
export interface Basis { x: Vec3; y: Vec3; z: Vec3; }
/** A unit axis and an angle in [0, π] radians. */
export interface AxisAngle { axis: Vec3; angle: number; }
/** Three angles in radians, in the order of an EulerOrder name. */
export interface EulerAngles { first: number; second: number; third: number; }
/** Tait–Bryan orders, intrinsic: 'zyx' is yaw, pitch, roll about z, y, x. */
export type EulerOrder = 'xyz' | 'xzy' | 'yxz' | 'yzx' | 'zxy' | 'zyx';
export interface Bounds3 { min: Vec3; max: Vec3; }
/** The nearest point of a 3-D path; no point of it is nearer than distance − gap. */
export interface Closest3 { u: number; point: Vec3; distance: number; gap: number; }
/** Frenet data at u: unit tangent, normal, binormal; curvature and torsion per world unit.
 *  normalDefined is false where the curvature is 0 (the normal is then any perpendicular). */
export interface Frenet3 {
  point: Vec3; tangent: Vec3; normal: Vec3; binormal: Vec3; curvature: number; torsion: number; normalDefined: boolean;
}
/** A moving frame: unit tangent, normal ⟂ tangent, binormal = tangent × normal. */
export interface Frame3 { point: Vec3; tangent: Vec3; normal: Vec3; binormal: Vec3; }

/** 3-D path kinds as Path3.kind() names them. */
export type Path3Kind = 'line' | 'quadratic_bezier' | 'cubic_bezier' | 'catmull_rom' | 'helix' | 'complex' | 'hermite' |
  'linear_spline' | 'arc' | 'projectile' | 'on_plane' | 'reparametrized' | 'slice';

/** Flat x, y, z triples. */
export type Points3 = ArrayLike<number>;

/** A 3-D path over u in [0, 1], an immutable value; extends along its end tangents outside [0, 1]. */
export interface Path3 extends Deletable {
  /** Position at u. */
  point(u: number): Vec3;
  /** dpoint/du, d²point/du², d³point/du³. */
  d1(u: number): Vec3;
  d2(u: number): Vec3;
  d3(u: number): Vec3;
  /** Unit tangent at u (never NaN: at zero speed the direction of d2, else d3). */
  tangent(u: number): Vec3;
  /** Tangent, normal, binormal, curvature and torsion at u (clamped to [0, 1]). */
  frenet(u: number): Frenet3;
  /** Arc length over [0, 1] (~1e-14 relative, or the closed form). */
  length(): number;
  /** Arc length over [0, u]. */
  lengthAt(u: number): number;
  /** The u where lengthAt(u) == s (s clamped to [0, length()]). */
  uAtLength(s: number): number;
  /** point(uAtLength(s)). */
  pointAtLength(s: number): Vec3;
  /** The u values, 0 and 1 included, where pieces meet (derivatives may jump there only). */
  breaks(): Float64Array;
  /** Tight axis-aligned box over [0, 1]. */
  bounds(): Bounds3;
  /** A polyline within `tolerance` of the path, as x, y, z triples. */
  flatten(tolerance: number): Float64Array;
  /** point(u) for each u, as x, y, z triples. */
  sample(us: ArrayLike<number>): Float64Array;
  /** The same shape at constant speed (arc length within 1e-9·length of exact). */
  reparametrized(): Path3;
  /** The part between u0 and u1 (0 ≤ u0 < u1 ≤ 1) as a path of its own. */
  slice(u0: number, u1: number): Path3;
  /** The globally nearest point to p (u in [0, 1]). */
  closestPoint(p: Vec3): Closest3;
  kind(): Path3Kind;
  /** A complex path's parts (0 for other kinds). */
  partCount(): number;
  part(i: number): Path3;
}

/** An exact helix about `axis` through `center`, from center + radius·start, rising `rise` per turn. */
export interface HelixOptions { center?: Vec3; axis?: Vec3; start?: Vec3; radius?: number; rise?: number; turns?: number; }
/** An exact circular arc from startAngle (u = 0) to endAngle (u = 1), radians, counter-clockwise about `axis`. */
export interface Arc3Options { center?: Vec3; axis?: Vec3; start?: Vec3; radius?: number; startAngle?: number; endAngle?: number; }

export interface Path3Static {
  /** A line of length 0 at the origin. */
  new(): Path3;
  line(a: Vec3, b: Vec3): Path3;
  quadraticBezier(p0: Vec3, p1: Vec3, p2: Vec3): Path3;
  cubicBezier(p0: Vec3, p1: Vec3, p2: Vec3, p3: Vec3): Path3;
  /** Through ≥ 2 points (closed: ≥ 3, joined back to the first); type default 'uniform'. */
  catmullRom(xyz: Points3, type?: 'uniform' | 'centripetal' | 'chordal', closed?: boolean): Path3;
  /** Cubic Hermite through ≥ 2 points with one tangent per point (d/dt of each segment's t in [0, 1]). */
  hermite(xyz: Points3, tangents: Points3, closed?: boolean): Path3;
  linearSpline(xyz: Points3, closed?: boolean): Path3;
  /** Defaults: centre 0, axis +z, start +x, radius 1, rise 0, one turn. */
  helix(options: HelixOptions): Path3;
  /** Defaults: centre 0, axis +z, start +x, radius 1, from 0 to 2π. */
  arc(options: Arc3Options): Path3;
  /** position + velocity·t + ½·acceleration·t², t = u·seconds. */
  projectile(position: Vec3, velocity: Vec3, acceleration: Vec3, seconds: number): Path3;
  /** A 2-D path on the plane origin + xAxis·x + yAxis·y (axes orthogonal, of equal length). */
  onPlane(path: Path, origin: Vec3, xAxis: Vec3, yAxis: Vec3): Path3;
  /** Part i spans u in [cues[i], cues[i+1]). */
  complex(parts: Path3[], cues: ArrayLike<number>): Path3;
  complexByLength(parts: Path3[]): Path3;
  /** Cubic Béziers through sampled points, each within `tolerance` (default 1); corners kept
   *  where chords turn by more than cornerAngle radians (default π/3). */
  fit(xyz: Points3, options?: { tolerance?: number; cornerAngle?: number }): Path3;
}

/** Frame modes: rotation-minimizing from `up`; twisted to meet `endUp`; closed up on a loop;
 *  world up with blends near the vertical (a camera, a coaster); Frenet. */
export type FrameModeName = 'rmf' | 'ends' | 'closed' | 'reference_up' | 'frenet';
/** How a Frames3 table is built (all optional; default an RMF from +z). */
export interface FramesOptions {
  mode?: FrameModeName;
  /** The normal at u = 0 (rmf, ends, closed) or the world up (reference_up). */
  up?: Vec3;
  /** Mode ends: the normal at u = 1. */
  endUp?: Vec3;
  /** Modes ends and closed: whole turns of twist added (an integer, either sign). */
  extraTurns?: number;
  /** Mode reference_up: half-angle of the cone about ±up where the frame leaves the world up, radians in [0.05, 1.5]. */
  cone?: number;
  /** Radians over the whole path, in [1e-13, 0.1] (default 1e-9). */
  tolerance?: number;
}
/** Frames along one path, built once; frame(u) is orthonormal within a few ulp. */
export interface Frames3 extends Deletable {
  /** The frame at u (clamped to [0, 1]). */
  frame(u: number): Frame3;
  /** The frame's rotation: +x to the tangent, +y to the normal, +z to the binormal. */
  orientation(u: number): Quat;
  /** Frames at many u: point, tangent, normal, binormal (12 numbers) per u. */
  sample(us: ArrayLike<number>): Float64Array;
  path(): Path3;
  mode(): FrameModeName;
  /** Modes ends and closed: the twist added from u = 0 to 1, radians; 0 otherwise. */
  twist(): number;
  /** Mode reference_up: stretches found inside the cone. */
  coneCount(): number;
  /** Arc length over [0, u] from the table (within ~1e-15 relative of Path3.lengthAt). */
  lengthAt(u: number): number;
}
export interface Frames3Static { new(path: Path3, options?: FramesOptions): Frames3; }

/** How a RollTrack fills between keys (all optional). */
export interface RollOptions {
  interpolation?: 'curves' | 'natural_spline' | 'clamped_spline';
  /** Mode curves: one curve (name or Curve) per interval, or none for linear. */
  curves?: (string | Curve)[];
  /** Mode clamped_spline: droll/ds at the first and last keys, radians per world unit. */
  startSlope?: number;
  endSlope?: number;
}
/** Roll angles (radians) keyed by arc length; each key's roll exactly at its s, held outside the keys. */
export interface RollTrack extends Deletable { rollAt(s: number): number; }
export interface RollTrackStatic {
  /** keys: flat s, roll pairs, s strictly increasing from ≥ 0. */
  new(keys: ArrayLike<number>, options?: RollOptions): RollTrack;
}
/** Frames rolled about the tangent by a RollTrack (normal toward binormal for a positive roll). */
export interface RolledFrames3 extends Deletable {
  frame(u: number): Frame3;
  /** The frame at arc length s (slower: a u_at_length solve). */
  frameAtLength(s: number): Frame3;
  /** The roll added at u, radians. */
  roll(u: number): number;
  orientation(u: number): Quat;
  /** 12 numbers per u, as Frames3.sample. */
  sample(us: ArrayLike<number>): Float64Array;
}
export interface RolledFrames3Static { new(frames: Frames3, roll: RollTrack): RolledFrames3; }
/** Automatic banking: atan(v²κ/g) clamped to maxAngle (all optional). */
export interface BankOptions {
  /** v, units per second (default 10). */
  speed?: number;
  /** g, units per second² (default 9.81). */
  gravity?: number;
  /** Radians in [0, π/2] (default π/4). */
  maxAngle?: number;
  /** World up (default +z). */
  up?: Vec3;
  /** Arc length of the averaging window (default 0: none). */
  smoothing?: number;
  /** bankTrack: keys evenly spaced in arc length, ≥ 2 (default 513). */
  samples?: number;
}

/** Where a world point lands: picture coordinates (y down), depth (larger is farther), and
 *  false visible behind a perspective camera's near plane. */
export interface Projected { point: Vec2; depth: number; visible: boolean; }
/** A projection of 3-D points (z up) to an unscaled picture plane. */
export interface View3 extends Deletable {
  project(p: Vec3): Projected;
  /** x, y, z triples in, x, y, depth triples out (x, y NaN where not visible). */
  projectMany(xyz: Points3): Float64Array;
  /** Unit direction from the viewer toward p. */
  viewDirection(p: Vec3): Vec3;
  /** The camera's position (perspective), or a point far back along the view (oblique). */
  eye(): Vec3;
  isPerspective(): boolean;
}
export interface View3Static {
  /** oblique(40°, 0.8). */
  new(): View3;
  /** Parallel, z up: y recedes at `angle` radians, scaled by recede in (0, 1]. */
  oblique(angle?: number, recede?: number): View3;
  /** A camera at eye looking at target; a point at depth d and lateral offset h lands at h / (d·tan(fovY/2)). */
  perspective(eye: Vec3, target: Vec3, up?: Vec3, fovY?: number): View3;
  /** A camera orbiting target: azimuth about z from +x, elevation above the xy plane, radians. */
  orbit(target: Vec3, distance: number, azimuth: number, elevation: number, fovY?: number): View3;
}

/** A C² orientation curve through keys at strictly increasing parameters (clamped outside). */
export interface QuatSpline extends Deletable {
  orientation(t: number): Quat;
  /** World axes, radians per unit of t. */
  angularVelocity(t: number): Vec3;
  size(): number;
  parameter(i: number): number;
  /** Key i as held: normalized and turned to the side of key i − 1. */
  key(i: number): Quat;
  keyAngularVelocity(i: number): Vec3;
  iterations(): number;
}
export interface QuatSplineStatic { new(params: ArrayLike<number>, keys: Quat[]): QuatSpline; }

/** A model axis: forward and up of a 3-D animation's orientation. */
export type Axis3Name = '+x' | '-x' | '+y' | '-y' | '+z' | '-z';
/** How a 3-D animation turns its slot's orientation (all optional). */
export interface Motion3Options {
  /** none: identity; frame: the path's moving frame; world: upright (yaw only) about worldUp. */
  align?: 'none' | 'frame' | 'world';
  /** The frame for align frame and the offsets, built at creation on the path played. */
  frames?: FramesOptions;
  /** A Frames3 of the path played (the reparametrized one with {speed}), used instead of `frames`. */
  sharedFrames?: Frames3;
  worldUp?: Vec3;
  /** The model's axis along the tangent (default '+z'). */
  forward?: Axis3Name;
  /** The model's axis on the frame's normal, ⟂ forward (default '+y'). */
  up?: Axis3Name;
  /** Turn by π about the normal on backward plays (default true). */
  faceTravel?: boolean;
  /** World units along the frame's normal and binormal. */
  normalOffset?: number;
  binormalOffset?: number;
}

export interface Grape {
  Path: PathStatic;
  ComplexPath: { prototype: ComplexPath };
  parseSvgPath(data: string): ComplexPath;
  Curve: CurveStatic;
  parseCurve(name: string): Curve;
  /** parseCurve(name).at(t). */
  ease(name: string, t: number): number;
  /** linear and the 30 Penner names. */
  curveNames(): string[];
  Engine: EngineStatic;
  Animation: { prototype: Animation };
  ParticleSystem: ParticleSystemStatic;
  Bead: BeadStatic;
  ParabolaRun: ParabolaRunStatic;
  runParabola(options: ParabolaOptions, dt: number, seconds: number): ParabolaSummary;
  BitVector: BitVectorStatic;
  PairBits: PairBitsStatic;
  KeyState: KeyStateStatic;
  SpritePlayer: SpritePlayerStatic;
  TileSheet: TileSheetStatic;
  Path3: Path3Static;
  Frames3: Frames3Static;
  RollTrack: RollTrackStatic;
  RolledFrames3: RolledFrames3Static;
  /** The bank at u, radians (positive leans into the curve on a frame whose normal is up). */
  bankAngle(path: Path3, u: number, options: BankOptions): number;
  /** A RollTrack of the bank at evenly spaced arc lengths: use it on reference_up frames with the same up. */
  bankTrack(path: Path3, options?: BankOptions): RollTrack;
  View3: View3Static;
  QuatSpline: QuatSplineStatic;
  /** The rotation by angle radians about axis (right-handed). */
  quatFromAxisAngle(axis: Vec3, angle: number): Quat;
  quatAxisAngle(q: Quat): AxisAngle;
  /** The rotation taking the world axes to a right-handed orthonormal basis (within 1e-5). */
  quatFromBasis(x: Vec3, y: Vec3, z: Vec3): Quat;
  quatToBasis(q: Quat): Basis;
  /** +x to the tangent, +y to the normal, +z to the binormal. */
  quatFromFrame(frame: Frame3): Quat;
  quatFromEuler(angles: EulerAngles, order: EulerOrder): Quat;
  quatToEuler(q: Quat, order: EulerOrder): EulerAngles;
  /** exp of half the rotation vector (axis × angle). */
  quatFromRotationVector(r: Vec3): Quat;
  quatRotationVector(q: Quat): Vec3;
  /** (w, x, y, z) normalized; all zero or not finite throws. */
  unitQuat(w: number, x: number, y: number, z: number): Quat;
  /** The Hamilton product a·b: the rotation b, then a. */
  quatMultiply(a: Quat, b: Quat): Quat;
  quatConjugate(q: Quat): Quat;
  quatNormalized(q: Quat): Quat;
  /** v rotated by the unit quaternion q. */
  quatRotate(q: Quat, v: Vec3): Vec3;
  /** Shortest-arc slerp: the angle from a grows linearly in t. */
  quatSlerp(a: Quat, b: Quat, t: number): Quat;
}

/** Loads the module: `const grape = await require('grape-wasm')();`. */
declare function loadGrape(options?: object): Promise<Grape>;
export default loadGrape;
