//! Generator of the book's computed numbers (being written: issue 9).

fn main() {}
