//! The expression tree of a printed display.

/// An expression of the note.
#[derive(Clone, Debug, PartialEq)]
pub enum Expr {
    /// An integer literal.
    Int(i64),
    /// A symbol, by its canonical LaTeX key (`F_{w}`, `\dot{\theta}`, `\mathbf{x}_{\text{cm}}`).
    Sym(String),
    /// `\text{const}`: "does not change in time".
    Const,
    /// −a.
    Neg(Box<Expr>),
    /// a + b.
    Add(Box<Expr>, Box<Expr>),
    /// a − b.
    Sub(Box<Expr>, Box<Expr>),
    /// a b (implicit product; scalar times scalar or vector).
    Mul(Box<Expr>, Box<Expr>),
    /// a / b (`\frac`).
    Div(Box<Expr>, Box<Expr>),
    /// a^n (for a vector and n = 2: a·a).
    Pow(Box<Expr>, u32),
    /// a × b (`\times`, Milne's `\wedge`).
    Cross(Box<Expr>, Box<Expr>),
    /// sin of the argument (only θ evaluates: the state carries sin θ).
    Sin(Box<Expr>),
    /// cos of the argument.
    Cos(Box<Expr>),
    /// (a, b) or (a, b, c): a vector in the plane / in space.
    Tuple(Vec<Expr>),
    /// Σ over the particles of the operand (`\sum_i`, Milne's bare `\sum`).
    Sum(Box<Expr>),
    /// d/dt of the operand, along the motion.
    Deriv(Box<Expr>),
    /// ∂(operand)/∂(variable key), the other state variables held fixed.
    Partial(Box<Expr>, String),
    /// `…|_z`: the z component.
    ZComp(Box<Expr>),
    /// `…\Big|_{a=b=…}` or `[…]_{a=b}`: the operand, at an instant where the condition holds.
    At(Box<Expr>, Vec<Expr>),
}

/// How two consecutive forms of a chain are joined.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rel {
    /// `=`.
    Eq,
    /// `\equiv` (a definition of the right side).
    Defines,
}

/// Forms joined by `=` / `\equiv`: every form must have the same value.
#[derive(Clone, Debug, PartialEq)]
pub struct Chain {
    /// The forms, in print order.
    pub forms: Vec<Expr>,
    /// The printed LaTeX of each form (whitespace-trimmed), for reports.
    pub texts: Vec<String>,
    /// The relation before each form after the first.
    pub rels: Vec<Rel>,
}

/// One statement of a display.
#[derive(Clone, Debug, PartialEq)]
pub struct Statement {
    /// The chain.
    pub chain: Chain,
    /// `premise \Rightarrow conclusion`: the conclusion, when present.
    pub implies: Option<Chain>,
    /// True in Milne's notation (after `\text{Milne : }`).
    pub milne: bool,
}

/// A whole display: its statements, separated by `,\quad` (or by Milne's label).
#[derive(Clone, Debug, PartialEq)]
pub struct Display {
    /// The statements, in print order.
    pub statements: Vec<Statement>,
}

impl Display {
    /// Number of printed forms (every side of every chain, premises and conclusions).
    pub fn form_count(&self) -> usize {
        self.statements
            .iter()
            .map(|s| s.chain.forms.len() + s.implies.as_ref().map_or(0, |c| c.forms.len()))
            .sum()
    }
}
