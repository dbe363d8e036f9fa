// Tessendorf's FFT ocean on the GPU, in fragment passes (so WebGL2 runs the same code). Each
// wave of a lattice (the pool's, a sea cascade's) is advanced analytically, h = a0 e^{-i w t}
// + a1 e^{+i w t} with w^2 = g k tanh(k D) (1 + (k/k_m)^2), and turned into the spectra of
// the fields: the height and slopes (two complex signals per texel) and, with choppiness, the
// horizontal displacement D = sum(-i k/|k| h e^{ik.x}) and its derivatives (two more, a
// second target). Then Stockham's stages of radix FFT_RADIX (a module per radix: the loop
// over a stage's inputs must unroll, software rasterisers crawl through a loop of unknown
// length) along the rows, then the columns, sum the waves (inverse DFT). ambient/ocean.rs and
// ambient/fft.rs run the very same arithmetic on the CPU (`advance`, `advance_choppy`,
// `stockham_gather`).
// Several lattices of one size (the sea's cascades) may lie side by side, N texels wide
// each: every pass handles them all, each with its own band.

struct FftStage {
    // y: the stage's span L, the length of the sums the stages before it made (1, then the
    // product of their radices); z: 0 along rows, 1 along columns; w: the first column read,
    // for a pass that writes one lattice into a target of its own (0 otherwise).
    params: vec4<f32>,
    // x: time since the spectrum's epoch (s); y: log2 N.
    time: vec4<f32>,
    // Each lattice's band: x: pi / half the tile's side (rad/m, the wavenumber of one lattice
    // step); y: the water's depth (m).
    bands: array<vec4<f32>, FFT_MAX_LATTICES>,
};

@group(0) @binding(0) var<uniform> stage: FftStage;
// The spectrum pass: a0, a1 per lattice point (ocean.rs epoch_spectrum), in both. A stage: the
// previous pass's surface fields and displacement fields.
@group(0) @binding(1) var surface_in: texture_2d<f32>;
@group(0) @binding(2) var displacement_in: texture_2d<f32>;

struct BothFields {
    @location(0) surface: vec4<f32>,
    @location(1) displacement: vec4<f32>,
};

fn complex_mul(a: vec2<f32>, b: vec2<f32>) -> vec2<f32> {
    return vec2<f32>(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x);
}

// Angular frequency (rad/s) of a wave of wavenumber k (rad/m): gravity on water `depth` (m)
// deep, and surface tension (ambient.rs angular_frequency_in). tanh's argument is capped at 9
// (tanh 9 = 1 - 3e-8): some GPUs compute tanh from exponentials that overflow to inf/inf.
fn wave_frequency(k: f32, depth: f32) -> f32 {
    let ratio = k / CAPILLARY_WAVENUMBER;
    return sqrt(GRAVITY * k * tanh(min(k * depth, 9.0)) * (1.0 + ratio * ratio));
}

// Wavenumber (rad/m) of lattice index i along one axis, `step` (rad/m) apart: indices past
// N/2 are negative.
fn lattice_k(i: i32, n: i32, step: f32) -> f32 {
    return f32(select(i - n, i, i < n / 2)) * step;
}

// 1/|k|, 0 at k = 0 (no wave there).
fn inverse_k(k: vec2<f32>) -> f32 {
    return select(0.0, 1.0 / length(k), dot(k, k) > 0.0);
}

// The fields' spectra at lattice point `texel` of lattices `n` wide: its wave advanced, then
// h + i (i kx h) and i kz h + i (kx kz / k) h (dh/dz, and dDx/dz for choppiness); with
// `both`, also Dx + i Dz = (kz/k - i kx/k) h and dDx/dx + i dDz/dz = (kx^2/k + i kz^2/k) h.
fn fields_spectrum(texel: vec2<i32>, n: i32, both: bool) -> array<vec4<f32>, 2> {
    let band = stage.bands[texel.x >> u32(stage.time.y)];
    let a = textureLoad(surface_in, texel, 0);
    let k = vec2<f32>(lattice_k(texel.x & (n - 1), n, band.x), lattice_k(texel.y, n, band.x));
    let phase = wave_frequency(length(k), band.y) * stage.time.x;
    let turn = vec2<f32>(cos(phase), sin(phase));
    let h = complex_mul(a.xy, vec2<f32>(turn.x, -turn.y)) + complex_mul(a.zw, turn);
    let r = inverse_k(k);
    let c = k.y + k.x * k.y * r;
    var out = array<vec4<f32>, 2>(vec4<f32>(h - k.x * h, -c * h.y, c * h.x), vec4<f32>(0.0));
    if both {
        out[1] = vec4<f32>(complex_mul(vec2<f32>(k.y * r, -k.x * r), h), complex_mul(vec2<f32>(k.x * k.x * r, k.y * k.y * r), h));
    }
    return out;
}

// One output of a Stockham stage, as a gather: output o along the axis is
// sum_s in[i + s N/R] e^{+2 pi i s r / (R L)}, with r = o mod RL and i = (o / RL) L + r mod L.
fn stage_sum(position: vec4<f32>, both: bool) -> array<vec4<f32>, 2> {
    let texel = vec2<i32>(position.xy) + vec2<i32>(i32(stage.params.w), 0);
    let n = i32(textureDimensions(surface_in).y);
    let span = i32(stage.params.y);
    let block = FFT_RADIX * span;
    let stride = n >> FFT_RADIX_LOG2;
    let along_columns = stage.params.z > 0.5;
    // Along rows, the index within this texel's lattice (whose first column is `first`).
    // Every length is a power of two: masks and shifts, not divisions.
    let first = texel.x & ~(n - 1);
    let o = select(texel.x - first, texel.y, along_columns);
    let r = o & (block - 1);
    let i = ((o - r) >> FFT_RADIX_LOG2) + (r & (span - 1));
    var sums = array<vec4<f32>, 2>(vec4<f32>(0.0), vec4<f32>(0.0));
    for (var s = 0; s < FFT_RADIX; s++) {
        let index = i + s * stride;
        let at = select(vec2<i32>(first + index, texel.y), vec2<i32>(texel.x, index), along_columns);
        var x = array<vec4<f32>, 2>(textureLoad(surface_in, at, 0), vec4<f32>(0.0));
        if both {
            x[1] = textureLoad(displacement_in, at, 0);
        }
        let angle = 2.0 * PI * f32((s * r) & (block - 1)) / f32(block);
        let w = vec2<f32>(cos(angle), sin(angle));
        sums[0] += vec4<f32>(complex_mul(w, x[0].xy), complex_mul(w, x[0].zw));
        if both {
            sums[1] += vec4<f32>(complex_mul(w, x[1].xy), complex_mul(w, x[1].zw));
        }
    }
    return sums;
}

@fragment
fn fs_fft_spectrum_surface(in: FullscreenOut) -> @location(0) vec4<f32> {
    let n = i32(textureDimensions(surface_in).y);
    return fields_spectrum(vec2<i32>(in.position.xy), n, false)[0];
}

@fragment
fn fs_fft_spectrum_both(in: FullscreenOut) -> BothFields {
    let n = i32(textureDimensions(surface_in).y);
    let fields = fields_spectrum(vec2<i32>(in.position.xy), n, true);
    return BothFields(fields[0], fields[1]);
}

@fragment
fn fs_fft_surface(in: FullscreenOut) -> @location(0) vec4<f32> {
    return stage_sum(in.position, false)[0];
}

@fragment
fn fs_fft_both(in: FullscreenOut) -> BothFields {
    let sums = stage_sum(in.position, true);
    return BothFields(sums[0], sums[1]);
}
