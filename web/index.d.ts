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
}
export interface EngineStatic {
  new(capacity: number): Engine;
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
}

/** Loads the module: `const grape = await require('grape-wasm')();`. */
declare function loadGrape(options?: object): Promise<Grape>;
export default loadGrape;
