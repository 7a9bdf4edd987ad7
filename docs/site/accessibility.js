// Keyboard access to what scrolls sideways (WCAG 2.1.1; the axe rule scrollable-region-focusable). Added by
// mkdocs.yml's extra_javascript.
// - mkdocs-material wraps each table in a scrolling <div class="md-typeset__scrollwrap"> when the page loads:
//   each becomes a named region with tabindex 0, marked data-scrolls while it is too wide for its column;
// - a display equation wider than the page (at 320 px, or with WCAG text spacing) scrolls: it becomes a
//   region named "equation" with tabindex 0 while it does, and leaves the tab order when it fits again;
// - a block of code (tools/site_hooks.py makes each a region named "code") is a tab stop while it scrolls, named
//   "code, scrolls sideways", and leaves the tab order when it fits; so is a notebook output that scrolls, named
//   "output, scrolls sideways" (nbconvert made every output a tab stop of no name; the site hooks drop that);
// - material's search results box is a region named "search results" but no tab stop (tabindex -1): material makes it
//   one, yet Tab from the search box closes the search overlay, so the box would take the focus unseen (WCAG 2.4.7);
//   its results are reached from the search box by the arrow keys, as material intends (accessibility.css hides
//   the box while the overlay is closed).
const makeRegion = (element, name) => {
  element.setAttribute("tabindex", "0");
  element.setAttribute("role", "region");
  element.setAttribute("aria-label", name);
};

const markScrollingMath = () => {
  for (const math of document.querySelectorAll(".MathJax_Display, .MathJax_SVG_Display, mjx-container[display]")) {
    if (math.scrollWidth > math.clientWidth + 1) makeRegion(math, "equation");
    else if (math.getAttribute("aria-label") === "equation") {
      for (const name of ["tabindex", "role", "aria-label"]) math.removeAttribute(name);
    }
  }
};

const scrolls = (element) => element.scrollWidth > element.clientWidth + 1;
const SCROLLS = ", scrolls sideways";
const markScrollingBlocks = () => {
  for (const code of document.querySelectorAll('[role="region"][aria-label^="code"]')) {
    if (scrolls(code)) makeRegion(code, "code" + SCROLLS);
    else {
      code.removeAttribute("tabindex");
      code.setAttribute("aria-label", "code");
    }
  }
  for (const output of document.querySelectorAll(".jp-OutputArea-output")) {
    const overflow = getComputedStyle(output).overflowX;
    if (scrolls(output) && (overflow === "auto" || overflow === "scroll")) makeRegion(output, "output" + SCROLLS);
    else if (output.getAttribute("aria-label") === "output" + SCROLLS) {
      for (const name of ["tabindex", "role", "aria-label"]) output.removeAttribute(name);
    }
  }
};

// A table wider than its column scrolls sideways in its wrapper (material's, or a figure description's): the wrapper
// says so in words above the table (notebook-pages.css draws the note, data-scrolls turns it on), since an overlay
// scroll bar is not always shown.
const markScrollingTables = () => {
  for (const wrap of document.querySelectorAll(".md-typeset__scrollwrap, .figure-described-table")) {
    const scrolls = wrap.scrollWidth > wrap.clientWidth + 1;
    wrap.toggleAttribute("data-scrolls", scrolls);
    if (wrap.classList.contains("md-typeset__scrollwrap")) {  // a description's table keeps its own name
      wrap.setAttribute("aria-label", scrolls ? "table, scrolls sideways" : "table");
    }
  }
};

// - material's icons (inline SVG in the header, search, navigation, "Back to top" and footer) sit inside named links
//   and buttons, or beside text that says the same: a screen reader's tree lists each as an unnamed image, so
//   they are hidden from it (aria-hidden), as GitHub's copy icons already are.
const ICONS = ".md-header svg, .md-search svg, .md-nav svg, .md-top svg, .md-footer svg, .md-source svg, .md-content__button svg";
const hideIcons = () => {
  for (const icon of document.querySelectorAll(ICONS)) {
    if (!icon.hasAttribute("aria-label") && !icon.querySelector("title")) icon.setAttribute("aria-hidden", "true");
  }
};

document$.subscribe(() => {
  for (const wrap of document.querySelectorAll(".md-typeset__scrollwrap:not([tabindex])")) makeRegion(wrap, "table");
  for (const results of document.querySelectorAll(".md-search__scrollwrap")) {
    makeRegion(results, "search results");
    results.setAttribute("tabindex", "-1"); // a scrolling box with no tabindex is a tab stop in Chromium too
  }
  markScrollingTables();
  markScrollingBlocks();
  markScrollingMath();
  hideIcons();
});
let pending = false; // MathJax typesets after the page loads: look again, once a frame, whenever nodes come
new MutationObserver(() => {
  if (pending) return;
  pending = true;
  requestAnimationFrame(() => {
    pending = false;
    markScrollingMath();
  });
}).observe(document.body, {childList: true, subtree: true});
// a figure's longer description and an answer open closed: their tables and code are measured again when opened
document.addEventListener(
  "toggle",
  () => {
    markScrollingTables();
    markScrollingBlocks();
  },
  true,
);
window.addEventListener("resize", () => {
  markScrollingTables();
  markScrollingBlocks();
  markScrollingMath();
});
// Below Material's drawer breakpoint the site's navigation is a drawer off the screen's left edge; closed, its links
// stayed in the tab order, so focus went where no one could see it (WCAG 2.4.7 at 320 px). Inert while it is closed.
(() => {
  const drawer = document.getElementById("__drawer");
  const navigation = document.querySelector(".md-sidebar--primary");
  if (!drawer || !navigation) return;
  const narrow = window.matchMedia("(max-width: 76.234375em)"); // Material's own breakpoint for the drawer
  const update = () => {
    navigation.inert = narrow.matches && !drawer.checked;
  };
  drawer.addEventListener("change", update);
  narrow.addEventListener("change", update);
  update();
})();
