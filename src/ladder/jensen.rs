//! Jensen (Appendix A), eqs. (42)-(63), as printed.
