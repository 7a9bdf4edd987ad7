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
// stayed in the tab order, so focus went where no one could see it (WCAG 2.4.7 at 320 px): it is inert while closed.
// Material opens it by a click on the menu icon only (a <label> that takes no focus), so that icon becomes a button
// the keyboard reaches (WCAG 2.1.1), saying whether the drawer is open; Enter or Space opens it and puts the focus on
// its first link, Escape closes it and gives the focus back to the button.
(() => {
  const drawer = document.getElementById("__drawer");
  const navigation = document.querySelector(".md-sidebar--primary");
  const button = document.querySelector('label.md-header__button[for="__drawer"]');
  if (!drawer || !navigation) return;
  const narrow = window.matchMedia("(max-width: 76.234375em)"); // Material's own breakpoint for the drawer
  const update = () => {
    navigation.inert = narrow.matches && !drawer.checked;
    button?.setAttribute("aria-expanded", String(drawer.checked));
  };
  const open = (opened) => {
    drawer.checked = opened;
    update();
    if (opened) navigation.querySelector("a[href]")?.focus();
    else button?.focus();
  };
  if (button) {
    button.setAttribute("tabindex", "0");
    button.setAttribute("role", "button");
    button.setAttribute("aria-label", "The site's navigation");
    button.addEventListener("keydown", (event) => {
      if (event.key !== "Enter" && event.key !== " ") return;
      event.preventDefault();
      open(!drawer.checked);
    });
  }
  // Open, the drawer covers the page: Tab and Shift+Tab cycle through its links (a focus trap, as a dialog's), so the
  // focus never goes to the page hidden behind it (WCAG 2.4.3); Escape closes it, from anywhere in it.
  const stops = () =>
    [...navigation.querySelectorAll("a[href], button, input:not([type=checkbox]), [tabindex]:not([tabindex='-1'])")]
      .filter((stop) => stop.getClientRects().length && getComputedStyle(stop).visibility !== "hidden");
  document.addEventListener("keydown", (event) => {
    if (!drawer.checked || !narrow.matches) return;
    if (event.key === "Escape") open(false);
    if (event.key !== "Tab") return;
    const all = stops();
    if (!all.length) return;
    const at = all.indexOf(document.activeElement);
    const next = at < 0 ? 0 : (at + (event.shiftKey ? -1 : 1) + all.length) % all.length;
    if (at < 0 || (event.shiftKey && at === 0) || (!event.shiftKey && at === all.length - 1)) {
      event.preventDefault();
      all[next].focus();
    }
  });
  drawer.addEventListener("change", update);
  narrow.addEventListener("change", update);
  update();
})();
// The focus may land on a control of an embedded scene (a same-origin frame: srcdoc) that lies below the window's
// edge while the frame's top shows: the browser scrolls the frame's own page, not this one, so the focus was out of
// sight (WCAG 2.4.7, 2.4.3). This page now scrolls the least that brings the control into view, clear of the header.
const showFocusIn = (frame) => (event) => {
  const control = event.target.getBoundingClientRect?.();
  if (!control) return;
  const box = frame.getBoundingClientRect();
  const top = box.top + Math.max(control.top, 0), bottom = box.top + Math.min(control.bottom, frame.clientHeight);
  const header = document.querySelector(".md-header")?.getBoundingClientRect().bottom ?? 0;
  if (bottom > window.innerHeight) window.scrollBy(0, bottom - window.innerHeight + 8);
  else if (top < header) window.scrollBy(0, top - header - 8);
};
const watchFrames = () => {
  for (const frame of document.querySelectorAll("iframe")) {
    const watch = () => {
      const inner = frame.contentDocument; // null for a frame of another origin: the browser's own scrolling stays
      if (inner && !inner.toolkitWatched) {
        inner.toolkitWatched = true;
        inner.addEventListener("focusin", showFocusIn(frame));
      }
    };
    if (!frame.dataset.watched) {
      frame.dataset.watched = "1";
      frame.addEventListener("load", watch);
    }
    watch();
  }
};
document$.subscribe(watchFrames);
