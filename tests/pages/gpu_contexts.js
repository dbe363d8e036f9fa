// Counts GPU contexts: canvases' WebGL2/WebGPU contexts made, and those given back
// (WEBGL_lose_context.loseContext, GPUDevice.destroy). Before any other script.
// Loaded as a classic script ahead of the page's own (tests/pages/insert.html, many.html).
(() => {
  window.__gpu = { webgl2: 0, webgpu: 0, lostWebgl2: 0, destroyedDevices: 0 };
  /** Contexts made and not given back. */
  window.__gpuLive = () => {
    const g = window.__gpu;
    return g.webgl2 - g.lostWebgl2 + g.webgpu - g.destroyedDevices;
  };
  const getContext = HTMLCanvasElement.prototype.getContext;
  const made = new WeakSet();
  HTMLCanvasElement.prototype.getContext = function (type, ...rest) {
    const context = getContext.call(this, type, ...rest);
    if (context && (type === "webgl2" || type === "webgpu") && !made.has(context)) {
      made.add(context);
      window.__gpu[type]++;
      if (type === "webgl2") {
        const getExtension = context.getExtension.bind(context);
        context.getExtension = (name) => {
          const ext = getExtension(name);
          if (ext && name === "WEBGL_lose_context" && !ext.__counted) {
            const lose = ext.loseContext.bind(ext);
            ext.loseContext = () => { window.__gpu.lostWebgl2++; lose(); };
            ext.__counted = true;
          }
          return ext;
        };
      }
    }
    return context;
  };
  if (window.GPUDevice) {
    const destroy = GPUDevice.prototype.destroy;
    GPUDevice.prototype.destroy = function () { window.__gpu.destroyedDevices++; return destroy.call(this); };
  }
})();
