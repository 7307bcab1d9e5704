//! The book's page of the fall animated (`animation.html`): the SVG of `report::animation` for
//! `scenes/full-fall.toml`, simulated when the book is built, shown as an image (SMIL runs in an
//! `<img>`; no script), with what to watch for.

use super::pages::esc;

/// The animation's file in the book.
pub const FILE: &str = "figures/fall-animation.svg";

/// The animation of the full fall, or why there is none.
pub fn svg(root: &std::path::Path) -> Result<String, String> {
    let (scene, _) = super::generated::full_fall(root)?;
    let (scene, o) = crate::report::animation::run(&scene)?;
    crate::report::animation::svg(&scene, &o)
}

/// The page's body.
pub fn page() -> String {
    format!(
        "<h1>The fall, animated</h1>\n\
<p>The ladder of <code>scenes/full-fall.toml</code> released from rest at θ<sub>0</sub> = 0.3 rad, simulated \
when this book was built and played {slow}× slower than real time, then held for {hold} s. Every \
frame is a state the integrator computed: the angle θ and the centre's abscissa X. The three \
forces are drawn to one scale — blue the wall's push F<sub>w</sub> at the top, green the floor's push F<sub>f</sub> \
at the foot, red the weight m g at the centre.</p>\n\
<figure id=\"fall-animation\"><img src=\"{file}\" width=\"760\" height=\"460\" alt=\"{alt}\" />\
<figcaption>{alt}</figcaption></figure>\n\
<p>What to watch for. The wall force grows from zero, peaks and shrinks back to zero as the \
ladder tilts: the centre's outward speed stops growing there (F<sub>w</sub> = m ẍ<sub>cm</sub>, (6)). At that \
instant, marked by the dashed pose and the ring on the wall, the top leaves the wall \
(cos θ<sub>s</sub> = (2/3) cos θ<sub>0</sub>, the answer on the <a href=\"index.html#answer\">index</a>). After it the \
foot slides on at the centre's constant horizontal speed (<a href=\"phase2.html\">the floor \
phase</a>) and the floor force dips well below the weight before the ladder lands flat. \
<code>ladder animate SCENE --out FILE</code> draws any scene the same way.</p>\n",
        slow = crate::report::animation::SLOW,
        hold = crate::report::animation::HOLD,
        file = FILE,
        alt = esc("The ladder falls from release to flat; the wall force, the floor force and the weight are arrows to one scale; the separation from the wall is marked"),
    )
}
