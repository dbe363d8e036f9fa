// The CSP test pages' only script (inline scripts are refused there): records every policy
// violation of the page, then mounts the demo with the page's URL options.
import { mount } from "/embed.js";

window.__violations = [];
document.addEventListener("securitypolicyviolation", (e) =>
  window.__violations.push(`${e.violatedDirective}: ${e.blockedURI} (${e.sourceFile}:${e.lineNumber})`),
);
const options = Object.fromEntries(new URLSearchParams(location.search));
mount(document.getElementById("pool"), options).then((d) => (window.demo = d), () => {});
