// The explorer as a notebook widget (anywidget): the model's `html` trait is the
// self-contained explorer page of `scanline explain` (its data, style and the very
// explorer.js / quiz.js inlined), shown in a sandbox-free srcdoc iframe, so the
// widget needs no server and no network.  The `step` trait follows the page's step
// both ways.
function render({ model, el }) {
  const frame = document.createElement("iframe");
  frame.style.cssText = "width: 100%; height: 820px; border: 1px solid #d0d5dd; border-radius: 6px;";
  frame.title = "scanline explorer";
  let observer = null;
  const page = () => frame.contentWindow && frame.contentWindow.explorer;
  frame.addEventListener("load", () => {
    const body = frame.contentDocument.body;
    if (observer) observer.disconnect();
    observer = new MutationObserver(() => {          // the page stepped: tell the model
      const step = Number(body.dataset.step);
      if (Number.isInteger(step) && step !== model.get("step")) {
        model.set("step", step);
        model.save_changes();
      }
    });
    observer.observe(body, { attributes: true, attributeFilter: ["data-step"] });
    if (page() && model.get("step") > 0) page().go(model.get("step"));
  });
  const show = () => { frame.srcdoc = model.get("html"); };
  model.on("change:html", show);
  model.on("change:step", () => {                     // the model stepped: step the page
    const p = page();
    if (p && p.state.view && p.state.step !== model.get("step")) p.go(model.get("step"));
  });
  show();
  el.appendChild(frame);
  return () => { if (observer) observer.disconnect(); };
}
export default { render };
