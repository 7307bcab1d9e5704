//! A recursive-descent parser for the note's displays (the grammar is in the module docs of
//! [`crate::print`]).

use super::ast::{Chain, Display, Expr, Rel, Statement};
use super::lexer::{lex, Tok};

mod factor;

/// Parse a display into statements and chains of forms.
pub fn parse_display(src: &str) -> Result<Display, String> {
    let toks = lex(src)?;
    let mut p = Parser { toks, pos: 0 };
    let d = p.display()?;
    Ok(d)
}

/// Parse one expression (used for symbol-table keys and tests).
pub fn parse_expr(src: &str) -> Result<Expr, String> {
    let toks = lex(src)?;
    let mut p = Parser { toks, pos: 0 };
    let e = p.expr()?;
    if p.pos < p.toks.len() {
        return Err(format!("trailing input at {}", p.rest()));
    }
    Ok(e)
}

/// The canonical text of tokens (spaces dropped): how forms and symbol keys are compared.
pub fn render(toks: &[Tok]) -> String {
    let mut s = String::new();
    for (i, t) in toks.iter().enumerate() {
        match t {
            Tok::Cmd(w) => {
                s.push('\\');
                s.push_str(w);
                // `\times m` must not become `\timesm`.
                if matches!(toks.get(i + 1), Some(Tok::Letter(_))) {
                    s.push(' ');
                }
            }
            Tok::Letter(c) | Tok::Punct(c) => s.push(*c),
            Tok::Int(n) => s.push_str(&n.to_string()),
            Tok::Bar => s.push_str("\\Big|"),
            Tok::RowBreak => s.push_str("\\\\"),
        }
    }
    s
}

/// The canonical text of a LaTeX fragment.
pub fn canonical(src: &str) -> Result<String, String> {
    Ok(render(&lex(src)?))
}

struct Parser {
    toks: Vec<Tok>,
    pos: usize,
}

fn punct(c: char) -> Tok {
    Tok::Punct(c)
}

impl Parser {
    fn peek(&self) -> Option<&Tok> {
        self.toks.get(self.pos)
    }
    fn peek_at(&self, k: usize) -> Option<&Tok> {
        self.toks.get(self.pos + k)
    }
    fn is(&self, c: char) -> bool {
        self.peek() == Some(&punct(c))
    }
    fn is_cmd(&self, w: &str) -> bool {
        matches!(self.peek(), Some(Tok::Cmd(x)) if x == w)
    }
    fn eat(&mut self, c: char) -> bool {
        if self.is(c) {
            self.pos += 1;
            true
        } else {
            false
        }
    }
    fn expect(&mut self, c: char) -> Result<(), String> {
        if self.eat(c) {
            Ok(())
        } else {
            Err(format!("expected '{c}' at {}", self.rest()))
        }
    }
    fn rest(&self) -> String {
        let end = (self.pos + 6).min(self.toks.len());
        let r = render(&self.toks[self.pos.min(end)..end]);
        if r.is_empty() {
            "the end".into()
        } else {
            format!("'{r}'")
        }
    }
    /// `\text{Milne : }` / `\text{Milne: }` ahead.
    fn at_milne(&self) -> bool {
        self.is_cmd("text") && self.peek_at(2) == Some(&Tok::Letter('M'))
    }
    /// Skip `\text{Milne : }`: every token up to the brace that closes the label (`\text`
    /// itself is one of them).
    fn skip_milne(&mut self) {
        let mut depth = 0;
        while let Some(t) = self.peek().cloned() {
            self.pos += 1;
            match t {
                Tok::Punct('{') => depth += 1,
                Tok::Punct('}') => {
                    depth -= 1;
                    if depth == 0 {
                        break;
                    }
                }
                _ => {}
            }
        }
    }

    fn display(&mut self) -> Result<Display, String> {
        let mut statements = Vec::new();
        let mut milne = false;
        loop {
            while self.peek() == Some(&Tok::RowBreak) {
                self.pos += 1;
            }
            if self.at_milne() {
                self.skip_milne();
                milne = true;
            }
            if self.peek().is_none() {
                break;
            }
            let chain = self.chain()?;
            let implies = if self.is_cmd("Rightarrow") {
                self.pos += 1;
                Some(self.chain()?)
            } else {
                None
            };
            statements.push(Statement {
                chain,
                implies,
                milne,
            });
            while self.peek() == Some(&Tok::RowBreak) {
                self.pos += 1;
            }
            if self.eat(',') || self.eat('.') {
                continue;
            }
            if self.at_milne() || self.peek().is_none() {
                continue;
            }
            return Err(format!("expected ',' or the end at {}", self.rest()));
        }
        if statements.is_empty() {
            return Err("an empty display".into());
        }
        Ok(Display { statements })
    }

    fn chain(&mut self) -> Result<Chain, String> {
        let mut forms = Vec::new();
        let mut texts = Vec::new();
        let mut rels = Vec::new();
        loop {
            let start = self.pos;
            forms.push(self.expr()?);
            texts.push(render(&self.toks[start..self.pos]));
            let save = self.pos;
            while self.peek() == Some(&Tok::RowBreak) {
                self.pos += 1;
            }
            let rel = if self.eat('=') {
                Rel::Eq
            } else if self.is_cmd("equiv") {
                self.pos += 1;
                Rel::Defines
            } else {
                self.pos = save;
                break;
            };
            rels.push(rel);
            while self.peek() == Some(&Tok::RowBreak) {
                self.pos += 1;
            }
        }
        Ok(Chain { forms, texts, rels })
    }

    /// expr := [+|−] xterm ((+|−) xterm)*, row breaks inside a sum allowed.
    fn expr(&mut self) -> Result<Expr, String> {
        let mut e = if self.eat('-') {
            Expr::Neg(Box::new(self.xterm()?))
        } else {
            self.eat('+');
            self.xterm()?
        };
        loop {
            let save = self.pos;
            while self.peek() == Some(&Tok::RowBreak) {
                self.pos += 1;
            }
            if self.eat('+') {
                e = Expr::Add(Box::new(e), Box::new(self.xterm()?));
            } else if self.eat('-') {
                e = Expr::Sub(Box::new(e), Box::new(self.xterm()?));
            } else {
                self.pos = save;
                return Ok(e);
            }
        }
    }

    /// xterm := product ((\times|\wedge) product)* [|_z | \Big|_{cond}]
    fn xterm(&mut self) -> Result<Expr, String> {
        let mut e = self.product()?;
        while self.is_cmd("times") || self.is_cmd("wedge") {
            self.pos += 1;
            e = Expr::Cross(Box::new(e), Box::new(self.product()?));
        }
        self.postfix(e)
    }

    fn postfix(&mut self, mut e: Expr) -> Result<Expr, String> {
        loop {
            let bar = self.peek() == Some(&Tok::Bar) || self.is('|');
            if bar && self.peek_at(1) == Some(&punct('_')) {
                self.pos += 2;
                if self.peek() == Some(&Tok::Letter('z')) {
                    self.pos += 1;
                    e = Expr::ZComp(Box::new(e));
                } else {
                    e = Expr::At(Box::new(e), self.condition()?);
                }
            } else {
                return Ok(e);
            }
        }
    }

    /// `{a = b = …}` after an evaluation bar or bracket.
    fn condition(&mut self) -> Result<Vec<Expr>, String> {
        self.expect('{')?;
        let mut sides = vec![self.expr()?];
        while self.eat('=') {
            sides.push(self.expr()?);
        }
        self.expect('}')?;
        Ok(sides)
    }

    fn starts_factor(&self) -> bool {
        match self.peek() {
            Some(Tok::Letter(_)) | Some(Tok::Int(_)) => true,
            Some(Tok::Punct(c)) => matches!(c, '(' | '['),
            Some(Tok::Cmd(w)) => {
                !matches!(
                    w.as_str(),
                    "times" | "wedge" | "equiv" | "Rightarrow" | "end"
                ) && !self.at_milne()
            }
            _ => false,
        }
    }

    /// product := factor factor* (implicit products); Σ and d/dt take the rest of the term.
    fn product(&mut self) -> Result<Expr, String> {
        let mut factors: Vec<Expr> = Vec::new();
        while self.starts_factor() {
            if self.is_cmd("sum") {
                self.pos += 1;
                if self.eat('_') {
                    self.group_text()?;
                }
                let operand = self.xterm()?;
                factors.push(Expr::Sum(Box::new(operand)));
                break;
            }
            if self.derivative_operator() {
                let operand = self.xterm()?;
                factors.push(Expr::Deriv(Box::new(operand)));
                break;
            }
            factors.push(self.factor()?);
        }
        let mut it = factors.into_iter();
        let first = it
            .next()
            .ok_or_else(|| format!("expected a term at {}", self.rest()))?;
        Ok(it.fold(first, |a, b| Expr::Mul(Box::new(a), Box::new(b))))
    }

    /// `\frac{d}{dt}` ahead: consume it.
    fn derivative_operator(&mut self) -> bool {
        let want = [
            Tok::Cmd("frac".into()),
            punct('{'),
            Tok::Letter('d'),
            punct('}'),
            punct('{'),
            Tok::Letter('d'),
            Tok::Letter('t'),
            punct('}'),
        ];
        if self.toks[self.pos..].starts_with(&want) {
            self.pos += want.len();
            true
        } else {
            false
        }
    }

    /// A braced group (or one token) as canonical text.
    fn group_text(&mut self) -> Result<String, String> {
        if self.eat('{') {
            let start = self.pos;
            let mut depth = 1;
            while depth > 0 {
                match self.peek() {
                    None => return Err("unclosed '{'".into()),
                    Some(Tok::Punct('{')) => depth += 1,
                    Some(Tok::Punct('}')) => depth -= 1,
                    _ => {}
                }
                self.pos += 1;
            }
            Ok(render(&self.toks[start..self.pos - 1]))
        } else {
            let t = self
                .peek()
                .cloned()
                .ok_or_else(|| "expected a subscript".to_string())?;
            self.pos += 1;
            Ok(render(&[t]))
        }
    }

    /// A braced group parsed as an expression.
    fn group_expr(&mut self) -> Result<Expr, String> {
        self.expect('{')?;
        let e = self.expr()?;
        self.expect('}')?;
        Ok(e)
    }

    fn power(&mut self, e: Expr) -> Result<Expr, String> {
        if self.eat('^') {
            let n = match self.peek().cloned() {
                Some(Tok::Int(n)) => {
                    self.pos += 1;
                    n
                }
                Some(Tok::Punct('{')) => {
                    self.pos += 1;
                    let Some(Tok::Int(n)) = self.peek().cloned() else {
                        return Err(format!("expected an integer power at {}", self.rest()));
                    };
                    self.pos += 1;
                    self.expect('}')?;
                    n
                }
                _ => return Err(format!("expected a power at {}", self.rest())),
            };
            Ok(Expr::Pow(Box::new(e), n as u32))
        } else {
            Ok(e)
        }
    }
}
