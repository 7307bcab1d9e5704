//! Tests of `sliding_ladder::book::write` (src/book/write.rs).

use sliding_ladder::book::write::write_atomically;
use std::path::PathBuf;

fn scratch(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ladder-book-write-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn writes_replaces_its_own_book_and_refuses_anything_else() {
    let d = scratch("a");
    let out = d.join("book");
    let files = vec![("a/b.html".to_string(), b"x".to_vec())];
    write_atomically(&out, &files).unwrap();
    assert_eq!(std::fs::read(out.join("a/b.html")).unwrap(), b"x");
    // A second run replaces the first whole.
    write_atomically(&out, &[("c.html".to_string(), b"y".to_vec())]).unwrap();
    assert!(!out.join("a/b.html").exists() && out.join("c.html").exists());
    // A foreign directory, a file and a missing parent are refused, and nothing is left.
    let foreign = d.join("mine");
    std::fs::create_dir(&foreign).unwrap();
    std::fs::write(foreign.join("notes.txt"), "keep").unwrap();
    assert!(write_atomically(&foreign, &files)
        .unwrap_err()
        .contains("not a book"));
    assert_eq!(
        std::fs::read_to_string(foreign.join("notes.txt")).unwrap(),
        "keep"
    );
    std::fs::write(d.join("file"), "").unwrap();
    assert!(write_atomically(&d.join("file"), &files).is_err());
    assert!(write_atomically(&d.join("no/such/dir"), &files)
        .unwrap_err()
        .contains("does not exist"));
    let left: Vec<_> = std::fs::read_dir(&d)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(left.len(), 3, "only book, mine and file remain: {left:?}");
    // A file that cannot be written (a name that is a directory) leaves the old book as it was.
    let bad = vec![
        ("x".to_string(), b"1".to_vec()),
        ("x/y".to_string(), b"2".to_vec()),
    ];
    assert!(write_atomically(&out, &bad).is_err());
    assert!(out.join("c.html").exists());
    let _ = std::fs::remove_dir_all(&d);
}
