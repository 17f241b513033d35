//! The motion configuration (`MOC.cfg`), as far as programs see it: the robots and the
//! robot types they use (`ROBOT: -name "ROB_1" -use_robot_type "ROB1"`).

use crate::CfgFile;

/// One `ROBOT` instance.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Robot {
    pub name: String,
    /// `-use_robot_type`: the name of the `ROBOT_TYPE` instance.
    pub robot_type: Option<String>,
    pub line: u32,
}

/// The robots of a MOC file.
pub fn robots(file: &CfgFile) -> Vec<Robot> {
    file.instances("ROBOT")
        .filter_map(|inst| {
            let name = inst.name()?;
            let robot_type = inst.value("use_robot_type").map(str::to_owned);
            Some(Robot { name: name.to_owned(), robot_type, line: inst.line })
        })
        .collect()
}

/// The mechanical units of a MOC file that are not robots (`MECHANICAL_UNIT` instances
/// no `ROBOT` instance names): external axes, tracks, positioners.
pub fn external_units(file: &CfgFile) -> Vec<String> {
    let robots: Vec<String> = robots(file).into_iter().map(|r| r.name.to_ascii_uppercase()).collect();
    file.instances("MECHANICAL_UNIT")
        .filter_map(|inst| inst.name())
        .filter(|name| !robots.contains(&name.to_ascii_uppercase()))
        .map(str::to_owned)
        .collect()
}
