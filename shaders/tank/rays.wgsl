// What a ray meets in the tank's lab, shape by shape: the nearest hit's distance, normal and
// kind (what it is, for its colour). The box and sphere tests are the pool's (common.wgsl).

struct Hit {
    t: f32,
    normal: vec3<f32>,
    kind: i32, // 0 nothing, 1 water, 2 frame, 3 leg, cord or rod, 4 bulb, 5 bench and paper, 6 a source
};

fn no_hit() -> Hit {
    return Hit(NO_HIT, vec3<f32>(0.0, 1.0, 0.0), 0);
}

fn nearer(a: Hit, b: Hit) -> Hit {
    if b.t < a.t {
        return b;
    }
    return a;
}

// The ray's nearest entry into the box from `lo` to `hi` beyond 1e-4; its normal is the face's
// it enters by (the axis along which the entry lies farthest out, as a share of the box).
fn box_hit(o: vec3<f32>, d: vec3<f32>, lo: vec3<f32>, hi: vec3<f32>, kind: i32) -> Hit {
    let t = intersect_box(o, d, lo, hi);
    if t.x > t.y || t.x < 1e-4 {
        return no_hit();
    }
    let q = (o + t.x * d - 0.5 * (lo + hi)) / (0.5 * (hi - lo));
    let a = abs(q);
    let z_or_y = select(vec3<f32>(0.0, 0.0, 1.0), vec3<f32>(0.0, 1.0, 0.0), a.y >= a.z);
    let axis = select(z_or_y, vec3<f32>(1.0, 0.0, 0.0), a.x >= a.y && a.x >= a.z);
    return Hit(t.x, axis * sign(q), kind);
}

// A vertical rod of radius `r` round (c.x, c.y) from height y0 to y1.
fn rod_hit(o: vec3<f32>, d: vec3<f32>, c: vec2<f32>, r: f32, y0: f32, y1: f32) -> Hit {
    let p = o.xz - c;
    let a = dot(d.xz, d.xz);
    let b = dot(p, d.xz);
    let disc = b * b - a * (dot(p, p) - r * r);
    if a < 1e-12 || disc < 0.0 {
        return no_hit();
    }
    let t = (-b - sqrt(disc)) / a;
    let y = o.y + t * d.y;
    if t < 1e-4 || y < y0 || y > y1 {
        return no_hit();
    }
    return Hit(t, vec3<f32>((p + t * d.xz) / r, 0.0).xzy, 3);
}

fn sphere_hit(o: vec3<f32>, d: vec3<f32>, c: vec3<f32>, r: f32, kind: i32) -> Hit {
    let t = intersect_sphere(o, d, c, r);
    if t >= NO_HIT {
        return no_hit();
    }
    return Hit(t, normalize(o + t * d - c), kind);
}

fn plane_hit(o: vec3<f32>, d: vec3<f32>, y: f32, kind: i32) -> Hit {
    let t = (y - o.y) / d.y;
    if t > 1e-4 && abs(d.y) > 1e-9 {
        return Hit(t, vec3<f32>(0.0, sign(-d.y), 0.0), kind);
    }
    return no_hit();
}
