//! Tests of `sliding_ladder::show::find` (src/show/find.rs).

use sliding_ladder::show::find::{parse_query, parse_query_in, search, Query};

#[test]
fn numbers_lists_and_ranges() {
    assert_eq!(parse_query("25").unwrap(), Query::Numbers(vec![25]));
    assert_eq!(parse_query("(25)").unwrap(), Query::Numbers(vec![25]));
    assert_eq!(
        parse_query("23-25, 28").unwrap(),
        Query::Numbers(vec![23, 24, 25, 28])
    );
    assert!(parse_query("0").is_err() && parse_query("5-3").is_err());
    // Only displays of the note in use: a folder with (1)-(3) and (7).
    let known = [1, 2, 3, 7];
    assert_eq!(
        parse_query_in("2-7", &known).unwrap(),
        Query::Numbers(vec![2, 3, 7])
    );
    let e = parse_query_in("5", &known).unwrap_err();
    assert!(
        e.contains("'5' is not a display") && e.ends_with("1-3, 7)"),
        "{e}"
    );
    assert_eq!(
        parse_query("about D").unwrap(),
        Query::Words("about D".into())
    );
}

#[test]
fn words_find_titles_and_symbols() {
    let about_d: Vec<u32> = search("about D").iter().map(|h| h.number).collect();
    assert!(
        about_d.contains(&24) && about_d.contains(&25),
        "{about_d:?}"
    );
    // "about D" is not "about A".
    assert!(!about_d.contains(&16), "{about_d:?}");
    let lp: Vec<u32> = search("L'_P").iter().map(|h| h.number).collect();
    assert!(!lp.is_empty() && lp.iter().all(|&n| n >= 29), "{lp:?}");
    assert!(search("zebra").is_empty());
}
