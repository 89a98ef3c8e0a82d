//! Reading SPIR-V for tests/layout.rs: a module's instructions, a
//! struct's member offsets and its specialisation constants, as the shader
//! compiler assigned them.

/// A SPIR-V module's instructions after its header: (opcode, operands).
pub fn instructions(spirv: &[u8]) -> Vec<(u32, Vec<u32>)> {
    let words: Vec<u32> = spirv
        .chunks_exact(4)
        .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        .collect();
    assert_eq!(words[0], 0x0723_0203, "SPIR-V magic");
    let mut all = Vec::new();
    let mut i = 5;
    while i < words.len() {
        let (count, opcode) = ((words[i] >> 16) as usize, words[i] & 0xffff);
        all.push((opcode, words[i + 1..i + count].to_vec()));
        i += count.max(1);
    }
    all
}

/// OpName's string: after the target id, nul-terminated UTF-8.
pub fn op_name(ops: &[u32]) -> String {
    let bytes: Vec<u8> = ops[1..].iter().flat_map(|w| w.to_le_bytes()).collect();
    let s: Vec<u8> = bytes.into_iter().take_while(|&b| b != 0).collect();
    String::from_utf8_lossy(&s).into_owned()
}

/// Member offsets (by member index) of the struct named `name` in a SPIR-V module.
pub fn member_offsets(spirv: &[u8], name: &str) -> Vec<u32> {
    let mut ids = Vec::new();
    let mut offsets: Vec<(u32, u32, u32)> = Vec::new();
    for (opcode, ops) in instructions(spirv) {
        match opcode {
            5 if op_name(&ops) == name => ids.push(ops[0]),
            // OpMemberDecorate: struct, member, decoration (35 = Offset), value.
            72 if ops[2] == 35 => offsets.push((ops[0], ops[1], ops[3])),
            _ => {}
        }
    }
    // A struct used both in a block and as a private variable is two types
    // of one name; the block's is the one with offsets.
    let id = *ids
        .iter()
        .find(|id| offsets.iter().any(|o| o.0 == **id))
        .unwrap_or_else(|| panic!("no struct named {name} with member offsets"));
    let mut m: Vec<(u32, u32)> = offsets
        .iter()
        .filter(|o| o.0 == id)
        .map(|o| (o.1, o.2))
        .collect();
    m.sort();
    m.into_iter().map(|(_, off)| off).collect()
}

/// Every specialisation constant of a SPIR-V module that the optimiser
/// kept: (SpecId, its names, GLSL type: bool, int, uint or float). (A
/// local `const` copy of a constant is the same id: it has both names.)
pub fn spirv_constants(spirv: &[u8]) -> Vec<(u32, Vec<String>, String)> {
    use std::collections::HashMap;
    let (mut names, mut spec_ids, mut types) = (HashMap::new(), HashMap::new(), HashMap::new());
    let mut constants = Vec::new();
    for (opcode, ops) in instructions(spirv) {
        match opcode {
            5 => names
                .entry(ops[0])
                .or_insert_with(Vec::new)
                .push(op_name(&ops)),
            // OpDecorate target SpecId (1) value.
            71 if ops[1] == 1 => drop(spec_ids.insert(ops[0], ops[2])),
            20 => drop(types.insert(ops[0], "bool")),
            21 => drop(types.insert(ops[0], if ops[2] == 1 { "int" } else { "uint" })),
            22 => drop(types.insert(ops[0], "float")),
            // OpSpecConstantTrue, OpSpecConstantFalse, OpSpecConstant.
            48..=50 => constants.push((ops[0], ops[1])),
            _ => {}
        }
    }
    constants
        .into_iter()
        .filter_map(|(ty, id)| {
            let kind = (*types.get(&ty)?).to_string();
            Some((*spec_ids.get(&id)?, names.get(&id)?.clone(), kind))
        })
        .collect()
}
