//! The factors of the print's grammar: numbers, symbols with their accents and indices,
//! fractions, functions and groups. A child of [`super`] (the parser is one `impl` split over two
//! files so that each stays short); it reads the parent's token cursor directly.

use super::super::ast::Expr;
use super::super::lexer::Tok;
use super::{punct, render, Parser};

impl Parser {
    pub(super) fn factor(&mut self) -> Result<Expr, String> {
        match self.peek().cloned() {
            Some(Tok::Int(n)) => {
                self.pos += 1;
                self.power(Expr::Int(n))
            }
            Some(Tok::Punct('(')) => {
                self.pos += 1;
                let mut items = vec![self.expr()?];
                while self.eat(',') {
                    items.push(self.expr()?);
                }
                self.expect(')')?;
                let e = if items.len() == 1 {
                    items.pop().expect("one item")
                } else {
                    Expr::Tuple(items)
                };
                self.power(e)
            }
            Some(Tok::Punct('[')) => {
                self.pos += 1;
                let e = self.expr()?;
                self.expect(']')?;
                if self.is('_') && self.peek_at(1) == Some(&punct('{')) {
                    self.pos += 1;
                    let cond = self.condition()?;
                    return Ok(Expr::At(Box::new(e), cond));
                }
                Ok(e)
            }
            Some(Tok::Cmd(w)) if w == "frac" => {
                self.pos += 1;
                self.fraction()
            }
            Some(Tok::Cmd(w)) if w == "sin" || w == "cos" => {
                self.pos += 1;
                let mut n = 1;
                if self.eat('^') {
                    let Some(Tok::Int(k)) = self.peek().cloned() else {
                        return Err(format!("expected a power of \\{w}"));
                    };
                    self.pos += 1;
                    n = k as u32;
                }
                let arg = Box::new(self.symbol()?);
                let f = if w == "sin" {
                    Expr::Sin(arg)
                } else {
                    Expr::Cos(arg)
                };
                Ok(if n == 1 { f } else { Expr::Pow(Box::new(f), n) })
            }
            Some(Tok::Cmd(w)) if w == "text" => {
                self.pos += 1;
                let t = self.group_text()?;
                if t == "const" {
                    Ok(Expr::Const)
                } else {
                    Err(format!("unexpected \\text{{{t}}}"))
                }
            }
            Some(_) => {
                let s = self.symbol()?;
                self.power(s)
            }
            None => Err("unexpected end".into()),
        }
    }

    /// `\frac{A}{B}`: a quotient, d(X)/dt, or ∂X/∂Y.
    pub(super) fn fraction(&mut self) -> Result<Expr, String> {
        let num_start = self.pos;
        let is_d = self.peek_at(1) == Some(&Tok::Letter('d'));
        let is_partial = matches!(self.peek_at(1), Some(Tok::Cmd(w)) if w == "partial");
        if is_d || is_partial {
            // Look at the denominator first: `{dt}` or `{\partial …}`.
            self.group_text()?;
            let den_start = self.pos;
            let den = self.group_text()?;
            let num_end = den_start;
            if (is_d && den == "dt") || is_partial {
                let mut inner = Parser {
                    toks: self.toks[num_start + 2..num_end - 1].to_vec(),
                    pos: 0,
                };
                let operand = inner.expr()?;
                if inner.pos < inner.toks.len() {
                    return Err(format!(
                        "trailing input in a derivative at {}",
                        inner.rest()
                    ));
                }
                if is_partial {
                    let wrt = den
                        .strip_prefix("\\partial")
                        .ok_or("expected ∂ in the denominator")?;
                    return Ok(Expr::Partial(Box::new(operand), wrt.to_string()));
                }
                return Ok(Expr::Deriv(Box::new(operand)));
            }
            self.pos = num_start;
        }
        let a = self.group_expr()?;
        let b = self.group_expr()?;
        Ok(Expr::Div(Box::new(a), Box::new(b)))
    }

    /// A symbol: a letter or Greek letter, possibly in a font or under accents, then primes and
    /// a subscript; Milne's `\mathbf{H}(O)` takes its point as part of the name.
    pub(super) fn symbol(&mut self) -> Result<Expr, String> {
        let mut key = self.symbol_base()?;
        loop {
            if self.eat('\'') {
                key.push('\'');
            } else if self.is('_') {
                self.pos += 1;
                let sub = self.group_text()?;
                key.push_str(&format!("_{{{sub}}}"));
            } else {
                break;
            }
        }
        // Milne's H(O), H_r(G), Γ(O): a bold capital applied to a point.
        if key.starts_with("\\mathbf{")
            && self.is('(')
            && matches!(self.peek_at(1), Some(Tok::Letter(c)) if c.is_ascii_uppercase())
        {
            let close = if self.peek_at(2) == Some(&punct('\'')) {
                3
            } else {
                2
            };
            if self.peek_at(close) == Some(&punct(')')) {
                let arg = render(&self.toks[self.pos + 1..self.pos + close]);
                key.push_str(&format!("({arg})"));
                self.pos += close + 1;
            }
        }
        Ok(Expr::Sym(key))
    }

    pub(super) fn symbol_base(&mut self) -> Result<String, String> {
        match self.peek().cloned() {
            Some(Tok::Letter(c)) => {
                self.pos += 1;
                Ok(c.to_string())
            }
            Some(Tok::Cmd(w)) => {
                self.pos += 1;
                match w.as_str() {
                    "mathbf" | "boldsymbol" | "mathcal" | "dot" | "ddot" | "hat" | "tilde"
                    | "bar" => {
                        self.expect('{')?;
                        let inner = self.symbol_base()?;
                        self.expect('}')?;
                        Ok(format!("\\{w}{{{inner}}}"))
                    }
                    "sin" | "cos" | "frac" | "sum" | "text" | "partial" => {
                        Err(format!("unexpected \\{w} where a symbol belongs"))
                    }
                    _ => Ok(format!("\\{w}")),
                }
            }
            _ => Err(format!("expected a symbol at {}", self.rest())),
        }
    }
}
