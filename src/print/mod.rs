//! The note's printed LaTeX as the thing checked (issue 9).
//!
//! Each display of the note (as its section in `equations/*.md` prints it) is parsed
//! into an expression tree ([`ast`]), its symbols are mapped to quantities of the independent
//! models by one data file, `src/print/symbols.toml` ([`symbols`], [`quantity`]), and every form
//! is evaluated in any [`crate::scalar::Scalar`] ([`eval`]): f64 with running error bounds, exact
//! rationals, AD duals for every d/dt, so the registry's own machinery checks the print itself
//! (`crate::registry::print_check`). Where values cannot tell two points' symbols apart, the same
//! file says which points' symbols each section prints ([`own_point`]).
//!
//! # Grammar (recursive descent, [`parser`])
//! ```text
//! display   := statement ((',' | '.' | MILNE) statement)*          -- `\text{Milne : }` = MILNE
//! statement := chain ['\Rightarrow' chain]
//! chain     := expr (('=' | '\equiv') expr)*                        -- `\\` and `&` between rows
//! expr      := ['+'|'-'] xterm (('+'|'-') xterm)*
//! xterm     := product (('\times'|'\wedge') product)* postfix*
//! postfix   := '|_z' | '\Big|_{' expr ('=' expr)* '}'                -- component / evaluated at
//! product   := factor+ | factor* '\sum'['_i'] xterm | factor* '\frac{d}{dt}' xterm
//! factor    := INT ['^' n] | '(' expr (',' expr)* ')' ['^' n]          -- tuple = vector
//!            | '[' expr ']' ['_{' cond '}'] | '\frac{' expr '}{' expr '}'
//!            | '\frac{d' X '}{dt}' | '\frac{\partial' X '}{\partial' Y '}'
//!            | ('\sin'|'\cos') ['^' n] symbol | '\text{const}' | symbol ['^' n]
//! symbol    := base ('\'' | '_' group)* ['(' POINT ['\''] ')']      -- Milne's H(O), Γ(O)
//! base      := LETTER | '\'GREEK | ('\mathbf'|'\boldsymbol'|'\mathcal'|'\dot'|'\ddot'
//!              |'\hat'|'\tilde'|'\bar') '{' base '}'
//! ```
//! Layout (`\quad`, `\left`, `\right`, `\Big` before a delimiter, `aligned`) is dropped by the
//! [`lexer`]. Implicit products bind tighter than `\times`; `\sum` and `d/dt` take the rest of
//! their term; `\sin\theta` takes one symbol.
//!
//! # Why no crate
//! The LaTeX crates found (pulldown-latex, latex2mathml, latex-rust) produce presentation trees
//! for rendering; the general math parsers (mathlex, rust-latex-parser) produce generic trees
//! that do not know the note's conventions (`\frac{dL_A}{dt}` as a derivative, a dotted symbol as
//! d/dt, `\sin^2\theta`, Milne's `\mathbf{H}(O)` as one name, `|_z` and `\Big|_{x_P=0}`,
//! statements separated by `,\quad` and `\text{Milne : }`), so their trees would need the same
//! interpretation pass this parser is; the grammar above is small enough to own.
//!
//! # Garble repairs
//! None are needed: every display of the markdown parses as printed. The one structural fix is a
//! continuation, not a garble: (57) begins with `=`, continuing (56)'s chain from its last form
//! τ_P (`registry::print_check::continuation`, found from the markdown). Misprints are never
//! repaired here: they are recorded as errata and must fail (`registry::print_check::misprints`).
pub mod ast;
pub mod clash;
pub mod condition;
pub mod eval;
pub mod lexer;
pub mod own_point;
pub mod parser;
pub mod point;
pub mod quantity;
pub mod render;
pub mod symbols;
pub mod unicode;
