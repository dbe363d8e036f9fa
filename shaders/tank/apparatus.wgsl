// The ripple tank as it stands in the lab, ray-traced: the lamp's bulb hanging over the
// tray, the tray's frame on four legs, the water in its glass-bottomed tray and the white
// paper on the bench below with the lamp's image on it (the screen pass's light). Looking into
// the water, a ray reflects by Fresnel's law to the room and the lamp, and refracts through
// the water and the glass (Snell's law at each face; the thin flat glass shifts a ray but does
// not turn it) down to the paper. The rays' box and sphere tests and Fresnel's equations are
// the pool's (common.wgsl).

const BULB_RADIUS: f32 = 0.025;
const CORD_RADIUS: f32 = 0.003;
const LEG_RADIUS: f32 = 0.008;
const RIM_HEIGHT: f32 = 0.012;
const GLASS_THICKNESS: f32 = 0.006;
const FRAME: vec3<f32> = vec3<f32>(0.32, 0.25, 0.18);
const METAL: vec3<f32> = vec3<f32>(0.45, 0.46, 0.48);
const BULB: vec3<f32> = vec3<f32>(6.0, 5.4, 4.2);
const DIPPER: vec3<f32> = vec3<f32>(0.8, 0.78, 0.72);
// How high over the water the dippers' rods reach (m): to the vibrator above the tray.
const ROD_TOP: f32 = 0.12;

fn bulb_hit(o: vec3<f32>, d: vec3<f32>) -> Hit {
    return sphere_hit(o, d, vec3<f32>(0.0, pic.tray.z, 0.0), BULB_RADIUS, 4);
}

// The sources in the water: each dipper a ball half under the surface on its rod, the bar a
// beam lying in it on two rods. Only the eye's rays look for them (not the reflections), and
// only those that pass through the space over the tray they stand in.
fn sources_hit(o: vec3<f32>, d: vec3<f32>) -> Hit {
    var hit = no_hit();
    let w = pic.tray.x;
    let span = intersect_box(o, d, vec3<f32>(-w, -0.05, -w), vec3<f32>(w, ROD_TOP, w));
    if span.x > span.y || span.y < 0.0 {
        return hit;
    }
    for (var k = 0u; k < MAX_DIPPERS; k++) {
        let s = pic.dippers[k];
        if s.w > 0.5 {
            hit = nearer(hit, sphere_hit(o, d, vec3<f32>(s.x, 0.0, s.y), s.z, 6));
            hit = nearer(hit, rod_hit(o, d, s.xy, CORD_RADIUS, 0.0, ROD_TOP));
        }
    }
    let b = pic.bar;
    if b.w > 0.5 {
        let lo = vec3<f32>(-b.z, -b.y, b.x - b.y);
        hit = nearer(hit, box_hit(o, d, lo, vec3<f32>(b.z, b.y, b.x + b.y), 6));
        for (var k = 0; k < 2; k++) {
            let x = select(-0.5, 0.5, k == 1) * b.z;
            hit = nearer(hit, rod_hit(o, d, vec2<f32>(x, b.x), CORD_RADIUS, 0.0, ROD_TOP));
        }
    }
    return hit;
}

fn paper_level() -> f32 {
    return -pic.tray.y - pic.tray.w;
}

// Everything but the water the ray meets first.
fn solid_hit(o: vec3<f32>, d: vec3<f32>) -> Hit {
    let w = pic.tray.x;
    let rim = w * FRAME_SHARE;
    let bottom = -pic.tray.y - GLASS_THICKNESS;
    var hit = plane_hit(o, d, paper_level(), 5);
    hit = nearer(hit, rod_hit(o, d, vec2<f32>(0.0), CORD_RADIUS, pic.tray.z, pic.tray.z + 3.0));
    hit = nearer(hit, bulb_hit(o, d));
    // The frame and its legs, for the rays that pass where they stand.
    let reach = rim + LEG_RADIUS;
    let stand = intersect_box(o, d, vec3<f32>(-reach, paper_level(), -reach), vec3<f32>(reach, RIM_HEIGHT, reach));
    if stand.x > stand.y || stand.y < 0.0 {
        return hit;
    }
    // The frame: four bars round the water.
    hit = nearer(hit, box_hit(o, d, vec3<f32>(-rim, bottom, w), vec3<f32>(rim, RIM_HEIGHT, rim), 2));
    hit = nearer(hit, box_hit(o, d, vec3<f32>(-rim, bottom, -rim), vec3<f32>(rim, RIM_HEIGHT, -w), 2));
    hit = nearer(hit, box_hit(o, d, vec3<f32>(w, bottom, -w), vec3<f32>(rim, RIM_HEIGHT, w), 2));
    hit = nearer(hit, box_hit(o, d, vec3<f32>(-rim, bottom, -w), vec3<f32>(-w, RIM_HEIGHT, w), 2));
    let corner = 0.5 * (w + rim);
    for (var k = 0; k < 4; k++) {
        let c = vec2<f32>(select(-corner, corner, (k & 1) == 1), select(-corner, corner, (k & 2) == 2));
        hit = nearer(hit, rod_hit(o, d, c, LEG_RADIUS, paper_level(), bottom));
    }
    return hit;
}

// The paper's light at a point of the bench (the lamp's image where it has one).
fn paper_colour(p: vec3<f32>) -> vec3<f32> {
    let e = pic.screen.x;
    let uv = vec2<f32>(0.5 + p.x / (2.0 * e), 0.5 - p.z / (2.0 * e));
    if any(uv < vec2<f32>(0.0)) || any(uv > vec2<f32>(1.0)) {
        return BENCH * (0.4 + 0.6 * lamp_light(p, vec3<f32>(0.0, 1.0, 0.0)));
    }
    return paper_at(uv);
}

// Diffuse light from the lamp on a surface at `p` facing `n` (1 straight under it at 1 m).
fn lamp_light(p: vec3<f32>, n: vec3<f32>) -> f32 {
    let to_lamp = vec3<f32>(0.0, pic.tray.z, 0.0) - p;
    return max(dot(n, normalize(to_lamp)), 0.0) / max(dot(to_lamp, to_lamp), 0.05);
}

// The room, dim, its ceiling lit (the water's ripples show in its reflection); the bulb where
// the ray meets it.
fn room(o: vec3<f32>, d: vec3<f32>) -> vec3<f32> {
    if bulb_hit(o, d).kind == 4 {
        return BULB;
    }
    return mix(vec3<f32>(0.03, 0.03, 0.035), vec3<f32>(0.3, 0.3, 0.32), smoothstep(0.2, 0.9, d.y));
}

fn shade_solid(hit: Hit, o: vec3<f32>, d: vec3<f32>) -> vec3<f32> {
    let p = o + hit.t * d;
    switch hit.kind {
        case 2: {
            return FRAME * (0.15 + lamp_light(p, hit.normal));
        }
        case 3: {
            return METAL * (0.15 + lamp_light(p, hit.normal));
        }
        case 4: {
            return BULB;
        }
        case 5: {
            return paper_colour(p);
        }
        case 6: {
            return DIPPER * (0.2 + lamp_light(p, hit.normal));
        }
        default: {
            return room(o, d);
        }
    }
}

// The water's surface at tray point xz: its normal from the heights round it, and whether a
// barrier stands there.
fn water_normal(xz: vec2<f32>) -> vec4<f32> {
    let w = pic.tray.x;
    let p = vec2<i32>((xz + w) / (2.0 * w) * pic.screen.z);
    let dx = 2.0 * w / pic.screen.z;
    let slope = vec2<f32>(cell_of(p + vec2<i32>(1, 0)).x - cell_of(p - vec2<i32>(1, 0)).x,
        cell_of(p + vec2<i32>(0, 1)).x - cell_of(p - vec2<i32>(0, 1)).x) / (2.0 * dx);
    return vec4<f32>(normalize(vec3<f32>(-slope.x, 1.0, -slope.y)), select(0.0, 1.0, is_wall(p)));
}

fn apparatus(uv: vec2<f32>) -> vec3<f32> {
    let ndc = vec2<f32>(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0);
    let near = pic.apparatus_inverse_view_proj * vec4<f32>(ndc, 0.0, 1.0);
    let far = pic.apparatus_inverse_view_proj * vec4<f32>(ndc, 1.0, 1.0);
    let o = near.xyz / near.w;
    let d = normalize(far.xyz / far.w - o);
    let solid = nearer(solid_hit(o, d), sources_hit(o, d));
    let water = plane_hit(o, d, 0.0, 1);
    let p = o + water.t * d;
    if water.t >= solid.t || any(abs(p.xz) > vec2<f32>(pic.tray.x)) {
        return shade_solid(solid, o, d);
    }
    let surface = water_normal(p.xz);
    if surface.w > 0.5 {
        return vec3<f32>(0.35) * (0.2 + lamp_light(p, vec3<f32>(0.0, 1.0, 0.0)));
    }
    // From above (or, under the tray, from below through the glass): Fresnel's share
    // reflected, the rest through the water and the glass.
    let n = select(-surface.xyz, surface.xyz, d.y < 0.0);
    let reflectance = fresnel(abs(dot(d, n)), select(IOR_WATER, 1.0 / IOR_WATER, d.y < 0.0));
    let reflected = reflect(d, n);
    let r_hit = solid_hit(p, reflected);
    // The room and the bulb in the water, and the bulb's glints on the ripples (a glossy lobe:
    // the surface is not a perfect mirror at a pixel's scale).
    let to_lamp = normalize(vec3<f32>(0.0, pic.tray.z, 0.0) - p);
    let glint = BULB * 0.02 * pow(max(dot(reflected, to_lamp), 0.0), 2000.0);
    let mirror = select(room(p, reflected), shade_solid(r_hit, p, reflected), r_hit.kind != 0) + glint;
    var through = vec3<f32>(0.0);
    if d.y < 0.0 {
        let t = refract(d, n, 1.0 / IOR_WATER);
        let bottom = p + t * ((-pic.tray.y - p.y) / t.y);
        let across = t.xz * IOR_WATER;
        let s2 = dot(across, across);
        if s2 < 1.0 {
            let out = vec3<f32>(across.x, -sqrt(1.0 - s2), across.y);
            through = shade_solid(solid_hit(bottom, out), bottom, out) * vec3<f32>(0.9, 0.95, 0.95);
        }
    } else {
        through = room(p, d);
    }
    return mix(through, mirror, reflectance);
}

@fragment
fn fs_apparatus(in: FullscreenOut) -> @location(0) vec4<f32> {
    let uv = vec2<f32>((in.uv.x - pic.halves.x) / pic.halves.y, in.uv.y);
    var colour = apparatus(uv);
    if ENCODE_SRGB {
        colour = linear_to_srgb(colour);
    }
    return vec4<f32>(colour, 1.0);
}
