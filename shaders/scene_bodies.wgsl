// What every kind of floating body shares in the scene's rays: the hit a kind's tracer returns,
// its wet band and glossy coat over the diffuse light of the scene it is in (object_colour,
// scene_seen.wgsl in the pool), and its blended outline. Each kind's own tracing and colour is
// in body_<kind>.wgsl; the code that asks every kind present (hit_bodies, body_colour,
// objects_visibility, bodies_occlusion) is written by bodies::wgsl from the table of kinds.

// What a ray hits on an object: distance (NO_HIT for nothing), outward normal, colour, and
// how far (m) the ray passes outside the object (negative: inside its outline; it runs on
// smoothly across the outline, so that its change to the next pixel gives an edge's blend).
struct ObjectHit {
    t: f32,
    normal: vec3<f32>,
    albedo: vec3<f32>,
    gap: f32,
};

// How wet a body's surface at p is: 1 at the water's rest level and under it, 0 from `band`
// (m) above it, where the water it rides up and down on has not reached.
fn wetness(p: vec3<f32>, band: f32) -> f32 {
    return 1.0 - smoothstep(0.0, band, p.y);
}

// A glossy coat over a body above the water, at a point with outward normal n seen along dir:
// Schlick's Fresnel (r0 = 0.04, an index of about 1.5) mirroring the sky, and the sun's
// highlight, a lobe cos^gloss about the mirror direction with `shine` times the sun's light at
// its peak (the sky's disk is a mirror's sun; the lobe is the sun blurred by a coat that is
// not one). A wet surface (wetness 1) mirrors up to twice as much, never more than all. Below
// the horizon the coat mirrors the water the body floats on: the sky mirrored again by
// Schlick's Fresnel for water (WATER_R0, 0.02), over the light coming up out of it (each scene's
// light_from_water), not the sky's ground.
fn clear_coat(n: vec3<f32>, dir: vec3<f32>, wet: f32, gloss: f32, shine: f32) -> vec3<f32> {
    let fresnel = 0.04 + 0.96 * pow(1.0 - max(dot(-dir, n), 0.0), 5.0);
    let r = reflect(dir, n);
    let highlight = sun_light() * shine * pow(max(dot(r, scene.sun.xyz), 0.0), gloss);
    let water = select(1.0, WATER_R0 + (1.0 - WATER_R0) * pow(1.0 - abs(r.y), 5.0), r.y < 0.0);
    let mirrored = sky_colour(vec3<f32>(r.x, abs(r.y), r.z)) * water + light_from_water() * (1.0 - water);
    return min(fresnel * (1.0 + wet), 1.0) * (mirrored + highlight);
}

// A body kind's coat: how far above the rest level it is wet (m), how much of its diffuse
// colour it keeps there, and its highlight's exponent and peak (clear_coat).
struct Coat {
    wet_band: f32,
    wet_albedo: f32,
    gloss: f32,
    shine: f32,
};

// Lit colour of a coated body at p (outward normal n, colour albedo) seen along dir: diffuse
// (object_colour), darker where wet, and above the water its coat (under: see object_colour)
// if seen `direct`ly. A traced ray (direct false, a constant that compiles the coat away)
// sees the body in the water's mirror or through it, weighted by the water's reflectance or
// from under it: there a coat would add a few hundredths of what it adds seen directly.
fn coated_colour(p: vec3<f32>, n: vec3<f32>, albedo: vec3<f32>, dir: vec3<f32>, under: bool, direct: bool, coat: Coat) -> vec3<f32> {
    let wet = wetness(p, coat.wet_band);
    let colour = object_colour(p, n, albedo * mix(1.0, coat.wet_albedo, wet), under, direct);
    if (!direct) {
        return colour;
    }
    return colour + select(clear_coat(n, dir, wet, coat.gloss, coat.shine), vec3<f32>(0.0), under);
}

// The light a hollow body of thin plastic gives out from inside at a point of albedo `albedo`:
// the sun's light through the wall facing it (`wall`: the share one wall passes) fills it,
// bounces round its inside and leaves through the wall there, tinted by it, so its shadowed
// side glows as a beach ball's does against the sun. Of the sun's light on the body's
// cross-section (πr² for a ball), spread over its inside (4πr²) and raised by the bounces off
// its walls (1 / (1 - HOLLOW_WALL_REFLECTANCE): a film passing 0.55 and absorbing little
// reflects the rest), HOLLOW_GAIN reaches each point of a wall.
const HOLLOW_WALL_REFLECTANCE: f32 = 0.45;
const HOLLOW_GAIN: f32 = 0.25 / (1.0 - HOLLOW_WALL_REFLECTANCE);

fn light_from_inside(albedo: vec3<f32>, wall: f32) -> vec3<f32> {
    return albedo * sun_light() * (wall * wall * HOLLOW_GAIN);
}

// A ball's silhouette without stair-steps: its mesh grown by BALL_EDGE_GROWTH is drawn again
// after everything else, each pixel blended by the share of it the ball covers (a ramp one
// pixel footprint wide, centred on the outline), as the deck's edge is. The pixel's ray passes
// `miss` (m) from the centre; `point` is where it hits the ball or, past the outline, the
// outline's point nearest to it, which gives the colour.
struct BallEdge {
    point: vec3<f32>,
    cover: f32,
    // Nothing to blend: deep enough inside that the ball's own mesh has the pixel, or on the
    // far side of the water from the eye (across_water: the water's own edge hides it there).
    hidden: bool,
};

const BALL_EDGE_GROWTH: f32 = 1.1;

// A vertex of a body's outline mesh: the point `surface` (outward normal n) moved `by` (m)
// along n, then pushed back from the eye as far as that brought it nearer. Where the body
// faces the eye the grown mesh then lies behind the body's own mesh, which hides it: early
// depth testing skips those fragments on a GPU and on lavapipe, the outline's shader having no
// discard (SwiftShader tests depth after shading). Towards the outline the body curves away
// and the grown mesh lies in front of it again, so a part's outline over another part is still
// drawn. (Putting every vertex whose ray meets the body behind it hid more, but lost those.)
fn grown_rim(surface: vec3<f32>, n: vec3<f32>, by: f32) -> vec3<f32> {
    let grown = surface + n * by;
    let view = normalize(grown - scene.eye.xyz);
    return grown + view * (by * max(dot(n, -view), 0.0));
}

// Call in uniform control flow (it takes a screen derivative). world: the grown mesh's point.
fn ball_edge(world: vec3<f32>, ball: vec4<f32>) -> BallEdge {
    let eye = scene.eye.xyz;
    let dir = normalize(world - eye);
    let nearest = eye + dir * dot(ball.xyz - eye, dir);
    let miss = distance(nearest, ball.xyz);
    let footprint = max(fwidth(miss), 1.0e-6);
    let t = intersect_sphere(eye, dir, ball.xyz, ball.w);
    let outline = ball.xyz + ball.w * normalize(nearest - ball.xyz);
    let point = select(outline, eye + dir * t, t < NO_HIT);
    let cover = clamp(0.5 - (miss - ball.w) / footprint, 0.0, 1.0);
    let across = across_water(point);
    return BallEdge(point, cover, miss < ball.w - footprint || across || cover <= 0.0);
}
