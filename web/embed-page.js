// embed.html's script (a file, so the page runs under a strict Content-Security-Policy too):
// mounts the pool from the URL's options, without controls unless ?controls=1, and tells the
// parent page how it went and how tall it wants to be.
import { browserLanguage, mount } from "./embed.js";

const options = { controls: false, ...Object.fromEntries(new URLSearchParams(location.search)) };
// In the visitor's language unless the embed code names one.
options.lang ??= browserLanguage();
const tell = (message) => window.parent !== window && window.parent.postMessage(message, "*");
const pool = document.getElementById("pool");
mount(pool, options).then(
  (demo) => {
    window.demo = demo;
    document.documentElement.lang = demo.language();
    tell({ type: "wavepool:ready", backend: demo.stats().backend });
  },
  (error) => tell({ type: "wavepool:error", message: String((error && error.message) || error) }),
);
// The height the page wants for its width (the pool at 4:3 plus its controls, if shown).
const wanted = () => {
  const root = pool.shadowRoot && pool.shadowRoot.querySelector(".root");
  const controls = root && root.querySelector(".controls");
  const extra = controls ? controls.getBoundingClientRect().height + 8 : 0;
  tell({ type: "wavepool:height", height: Math.ceil((document.documentElement.clientWidth * 3) / 4 + extra) });
};
new ResizeObserver(wanted).observe(document.documentElement);
