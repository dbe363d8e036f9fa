# Shared helpers for the set-up scripts: install what is missing, skip what is present.

# Runs a command as root (directly when already root, else through sudo).
as_root() {
    if [ "$(id -u)" = 0 ]; then "$@"; else sudo "$@"; fi
}

# Installs the named Debian packages that are not installed yet.
ensure_apt_packages() {
    local missing=()
    for pkg in "$@"; do
        if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
            missing+=("$pkg")
        fi
    done
    if [ "${#missing[@]}" -gt 0 ]; then
        echo "==> installing Debian packages: ${missing[*]}"
        as_root apt-get update -qq
        DEBIAN_FRONTEND=noninteractive as_root apt-get install -y -qq "${missing[@]}" >/dev/null
    fi
}

# Makes sure cargo is on PATH (rustup's default location).
ensure_cargo() {
    if ! command -v cargo >/dev/null 2>&1 && [ -x "$HOME/.cargo/bin/cargo" ]; then
        export PATH="$HOME/.cargo/bin:$PATH"
    fi
    if ! command -v cargo >/dev/null 2>&1; then
        # No Rust at all: rustup's installer, with the toolchain the crate needs (rust-version).
        echo "==> installing Rust with rustup"
        command -v curl >/dev/null 2>&1 || ensure_apt_packages curl ca-certificates
        curl --proto '=https' --tlsv1.2 -sSf https://sh.rustup.rs | sh -s -- -y --profile minimal \
            --default-toolchain "$(sed -n 's/^rust-version = "\(.*\)"/\1/p' Cargo.toml)" --component rustfmt \
            || { echo "error: could not install Rust (https://rustup.rs); install it and run this again" >&2; exit 1; }
        export PATH="$HOME/.cargo/bin:$PATH"
    fi
}

# Adds clippy to the Rust toolchain when it is missing.
ensure_clippy() {
    if ! cargo clippy --version >/dev/null 2>&1; then
        echo "==> adding clippy to the Rust toolchain"
        rustup component add clippy
    fi
}

# Lints the native build (every target) and the browser build (wasm32 library); warnings fail.
run_clippy() {
    echo "==> cargo clippy (native, all targets; wasm32 library)"
    cargo clippy --locked --all-targets -- -D warnings
    cargo clippy --locked --target wasm32-unknown-unknown --lib --no-default-features -- -D warnings
}

# Adds the wasm32 target to the Rust toolchain when it is missing.
ensure_wasm_target() {
    if ! rustup target list --installed 2>/dev/null | grep -qx wasm32-unknown-unknown; then
        echo "==> adding the Rust target wasm32-unknown-unknown"
        rustup target add wasm32-unknown-unknown
    fi
}

# ensure_cargo_tool BINARY VERSION CRATE [cargo install flags...]
# Installs CRATE at exactly VERSION with cargo unless `BINARY --version` already reports it.
ensure_cargo_tool() {
    local bin="$1" version="$2" crate="$3"
    shift 3
    if ! "$bin" --version 2>/dev/null | grep -q " $version\b"; then
        echo "==> installing $crate $version with cargo (a few minutes, once)"
        cargo install "$crate" --version "$version" --force "$@"
    fi
}

# The version of a package in Cargo.lock, e.g. lock_version wasm-bindgen.
lock_version() {
    awk -v name="$1" '$0 == "name = \"" name "\"" { getline; gsub(/version = |"/, ""); print; exit }' Cargo.lock
}

# Puts npm's binaryen 132 (its wasm-opt) on PATH. Debian's binaryen corrupts wasm-bindgen output.
ensure_wasm_opt() {
    local dir="${XDG_CACHE_HOME:-$HOME/.cache}/wavepool/binaryen-132"
    if [ ! -x "$dir/node_modules/.bin/wasm-opt" ]; then
        echo "==> installing wasm-opt (npm binaryen@132.0.0)"
        mkdir -p "$dir"
        npm install --prefix "$dir" --no-audit --no-fund --silent binaryen@132.0.0 >/dev/null
    fi
    export PATH="$dir/node_modules/.bin:$PATH"
}

# The Fluent runtime the page loads for a language other than English (@fluent/bundle 0.19.1
# from npm, its one-file build); build_web copies it next to the catalogues.
fluent_bundle_js() {
    local dir="${XDG_CACHE_HOME:-$HOME/.cache}/wavepool/fluent-0.19"
    if [ ! -f "$dir/node_modules/@fluent/bundle/index.js" ]; then
        echo "==> installing @fluent/bundle 0.19.1 (npm)" >&2
        mkdir -p "$dir"
        npm install --prefix "$dir" --no-audit --no-fund --silent @fluent/bundle@0.19.1 >/dev/null || return 1
    fi
    echo "$dir/node_modules/@fluent/bundle/index.js"
}

# Everything the browser build needs: wasm target, Trunk, wasm-bindgen-cli matching the
# lockfile, wasm-opt. Then fetches crates so Trunk can build offline.
ensure_web_toolchain() {
    ensure_cargo
    command -v npm >/dev/null 2>&1 || ensure_apt_packages nodejs npm
    # The package's script and tests (Vite 7) need Node.js 20.19 or later.
    if ! node -e 'const [a, b] = process.versions.node.split(".").map(Number); process.exit(a > 20 || (a === 20 && b >= 19) ? 0 : 1)'; then
        echo "error: Node.js $(node --version) is too old: the build needs 20.19 or later (NodeSource's nodejs, or nvm)" >&2
        return 1
    fi
    ensure_wasm_target
    ensure_cargo_tool trunk 0.21.14 trunk --locked
    ensure_cargo_tool wasm-bindgen "$(lock_version wasm-bindgen)" wasm-bindgen-cli
    ensure_wasm_opt
    cargo fetch --locked >/dev/null
}

# The course hosts the browser tests put the pool in, pinned: reveal.js and axe-core from npm,
# MkDocs Material from PyPI in a virtual environment of its own (a few seconds each, once).
ensure_host_tools() {
    local dir="${XDG_CACHE_HOME:-$HOME/.cache}/wavepool"
    if [ ! -f "$dir/hosts/node_modules/reveal.js/package.json" ] \
        || ! grep -q '"version": "6.0.2"' "$dir/hosts/node_modules/reveal.js/package.json" \
        || ! grep -q '"version": "4.14.1"' "$dir/hosts/node_modules/axe-core/package.json" 2>/dev/null; then
        echo "==> installing reveal.js 6.0.2 and axe-core 4.14.1 (npm)"
        mkdir -p "$dir/hosts"
        npm install --prefix "$dir/hosts" --no-audit --no-fund --silent reveal.js@6.0.2 axe-core@4.14.1 >/dev/null
    fi
    # (grep reads all of pip's output: with -q it would stop early, and pipefail would see pip's
    # broken pipe as a missing install.)
    if ! "$dir/mkdocs/bin/pip" show mkdocs-material 2>/dev/null | grep -x "Version: 9.8.2" >/dev/null; then
        echo "==> installing MkDocs Material 9.8.2 (PyPI, in $dir/mkdocs)"
        command -v python3 >/dev/null 2>&1 || ensure_apt_packages python3
        python3 -m venv "$dir/mkdocs" 2>/dev/null || { ensure_apt_packages python3-venv; python3 -m venv "$dir/mkdocs"; }
        "$dir/mkdocs/bin/pip" install --quiet mkdocs-material==9.8.2
    fi
}

# The tools the package's tests use as a web developer would, pinned: Vite 7.3.8 and
# TypeScript 5.9.3 from npm (a few seconds, once). Test apps made under this folder find them.
ensure_package_tools() {
    local dir="${XDG_CACHE_HOME:-$HOME/.cache}/wavepool/package-tools"
    if ! grep -q '"version": "7.3.8"' "$dir/node_modules/vite/package.json" 2>/dev/null \
        || ! grep -q '"version": "5.9.3"' "$dir/node_modules/typescript/package.json" 2>/dev/null; then
        echo "==> installing Vite 7.3.8 and TypeScript 5.9.3 (npm)"
        mkdir -p "$dir"
        npm install --prefix "$dir" --no-audit --no-fund --silent vite@7.3.8 typescript@5.9.3 >/dev/null
    fi
}

# Writes release/, what a user downloads, from dist/ and target/npm-package (build_web first):
# the npm tarball, the single page, a zip of dist/ for a course platform, their SHA-256 sums.
make_release() {
    echo "==> writing release/ (npm tarball, single page, course zip, checksums)"
    local version stage=target/release-stage
    version=$(sed -n 's/^version = "\(.*\)"/\1/p' Cargo.toml | head -1)
    rm -rf release "$stage" && mkdir -p release "$stage/wavepool" || return 1
    npm pack ./target/npm-package --pack-destination release --silent >/dev/null || return 1
    cp dist/wavepool-standalone.html release/ || return 1
    # The folder a teacher uploads: the pages and the demo's files (the single page is its own download).
    (cd dist && find . -type f ! -name wavepool-standalone.html -exec cp --parents {} "../$stage/wavepool/" \;) || return 1
    printf '%s\n' "wavepool $version: upload this folder to your course's files and link its index.html (the whole demo)," \
        "or put <iframe src=\"wavepool/embed.html?controls=1\" width=\"800\" height=\"600\" allow=\"fullscreen\"></iframe> in a page." \
        > "$stage/wavepool/README.txt"
    (cd "$stage" && python3 -m zipfile -c "../../release/wavepool-$version-course.zip" wavepool) || return 1
    (cd release && sha256sum -- * > SHA256SUMS) || return 1
    # shellcheck disable=SC2012
    ls -l release | awk 'NR > 1 { printf "    %s %d bytes\n", $9, $5 }'
}

# Builds the browser demo into dist/ with Trunk (release, wasm-opt -Oz), offline.
build_web() {
    echo "==> building the browser demo (trunk build --release)"
    TRUNK_SKIP_VERSION_CHECK=true trunk build --release --offline || return 1
    # The message catalogues (Trunk copies locales/) and the Fluent runtime beside them: fetched
    # only for a language other than English, so not part of the page's download.
    local fluent
    fluent=$(fluent_bundle_js) || return 1
    cp "$fluent" dist/locales/fluent-bundle.js || return 1
    command -v python3 >/dev/null 2>&1 || ensure_apt_packages python3
    # The JavaScript without its comments, line for line (the download is budgeted).
    python3 scripts/strip_js_comments.py dist || return 1
    # The same page as one file that opens from disk and in sandboxed frames.
    python3 scripts/standalone.py dist || return 1
    # The npm package: the modules, the core, their types (from the core's tables), package.json.
    node scripts/package.mjs dist target/npm-package || return 1
    local wasm=dist/wavepool_bg.wasm js
    js=$(ls dist/*.js)
    # shellcheck disable=SC2086
    echo "    wasm $(stat -c %s "$wasm") bytes ($(gzip -9c "$wasm" | wc -c) gzip), JS $(cat $js | wc -c) bytes ($(cat $js | gzip -9c | wc -c) gzip)"
}
