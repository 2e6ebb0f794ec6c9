// Mutant schemata for glsl/snell: one file's every mutant written into the file at once, each behind
// SNELL_MUT(id) (tests/mutation/README.md). A site becomes `(SNELL_MUT(7) ? mutated : original)` and a dropped
// statement `if (!SNELL_MUT(9)) { statement }`, so the C++ tests are built once and choose their mutant at
// run time (SNELL_MUTANT), and the GLSL runtime gets the same text with SNELL_MUTANT a literal.
//
//   import { schemaOf } from "./schema.mjs";
//   const { text, mutants, unparsed } = schemaOf(source, { file: "optics/refract.glsl", firstId: 0 });
//
// The operators, as the suite's blind spots were named:
//   flip      a comparison: < and <=, > and >=, == and != exchanged
//   swap      the operands of a binary - or / (+ and * commute: a swap there is no mutant)
//   ulp       a float literal compared against (a threshold: a boundary a contract states exactly) moved
//             up by one ulp (0 becomes the smallest normal float)
//   10%       any float literal in a body (or the value of a `#define NAME <float>` default) times 1.1
//   int+1     any other integer literal in a body plus 1 (array sizes excepted)
//   drop      an expression statement (assignment, call, ++/--), break or continue removed
//   clamp     clamp(x, lo, hi) with one bound gone: max(x, lo), or min(x, hi)
// A 1-ulp change of an arithmetic constant moves a result by about an ulp, under every tolerance, so it is
// only made where a constant is a threshold. A function whose body the parser cannot follow (a
// preprocessor branch splitting a statement) keeps its text and is listed in `unparsed`.

const PUNCT = ["<<=", ">>=", "++", "--", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "==", "!=", "<=", ">=",
  "&&", "||", "^^", "<<", ">>", "::", "->", "+", "-", "*", "/", "%", "<", ">", "=", "!", "~", "&", "|", "^", "?",
  ":", ";", ",", ".", "(", ")", "[", "]", "{", "}"];

export function tokenize(src) {
  const toks = [];
  let i = 0, line = 1, lineStart = true;
  while (i < src.length) {
    const c = src[i];
    if (c === "\n") { ++line; ++i; lineStart = true; continue; }
    if (c === " " || c === "\t" || c === "\r") { ++i; continue; }
    if (src.startsWith("//", i)) { while (i < src.length && src[i] !== "\n") ++i; continue; }
    if (src.startsWith("/*", i)) {
      const end = src.indexOf("*/", i + 2);
      const stop = end < 0 ? src.length : end + 2;
      for (let k = i; k < stop; ++k) if (src[k] === "\n") ++line;
      i = stop;
      continue;
    }
    const start = i, startLine = line;
    if (c === "#" && lineStart) {
      while (i < src.length && src[i] !== "\n") {
        if (src[i] === "\\" && src[i + 1] === "\n") { i += 2; ++line; continue; }
        ++i;
      }
      toks.push({ kind: "pp", text: src.slice(start, i), line: startLine, start, end: i });
      continue;
    }
    lineStart = false;
    const num = /^(0[xX][0-9a-fA-F]+[uU]?|(\d+\.\d*|\.\d+|\d+)([eE][+-]?\d+)?[fFuU]?)/.exec(src.slice(i, i + 64));
    if (/[0-9]/.test(c) || (c === "." && /[0-9]/.test(src[i + 1] ?? ""))) {
      i += num[0].length;
      toks.push({ kind: "num", text: num[0], line: startLine, start, end: i });
      continue;
    }
    if (/[A-Za-z_]/.test(c)) {
      while (i < src.length && /[A-Za-z0-9_]/.test(src[i])) ++i;
      toks.push({ kind: "id", text: src.slice(start, i), line: startLine, start, end: i });
      continue;
    }
    const p = PUNCT.find((x) => src.startsWith(x, i));
    if (!p) throw new Error(`line ${line}: unexpected character '${c}'`);
    i += p.length;
    toks.push({ kind: "op", text: p, line: startLine, start, end: i });
  }
  return toks;
}

const BINARY = new Map([["||", 3], ["^^", 4], ["&&", 5], ["|", 6], ["^", 7], ["&", 8], ["==", 9], ["!=", 9],
  ["<", 10], [">", 10], ["<=", 10], [">=", 10], ["<<", 11], [">>", 11], ["+", 12], ["-", 12], ["*", 13], ["/", 13],
  ["%", 13]]);
const ASSIGN = new Set(["=", "+=", "-=", "*=", "/=", "%=", "<<=", ">>=", "&=", "|=", "^="]);
const FLIP = { "<": "<=", "<=": "<", ">": ">=", ">=": ">", "==": "!=", "!=": "==" };
const QUALIFIERS = new Set(["const", "highp", "mediump", "lowp", "SNELL_PRECISE", "precise", "static"]);

function floatOf(text) {
  return Number(text.replace(/[fF]$/, ""));
}
// The float32 literal one ulp above x (0: the smallest normal float).
function ulpUp(x) {
  if (x === 0) return 1.17549435e-38;
  const f = new Float32Array([x]);
  const u = new Uint32Array(f.buffer);
  u[0] += x > 0 ? 1 : -1;
  return f[0];
}
function floatLiteral(x) {
  let s = String(Math.fround(x));
  if (!/[.eE]/.test(s)) s += ".0";
  return `${s}f`;
}

class Parser {
  constructor(toks, ctx) {
    this.t = toks;
    this.i = 0;
    this.ctx = ctx;
  }
  peek(k = 0) { return this.t[this.i + k]; }
  at(text, k = 0) { const x = this.peek(k); return x !== undefined && x.kind !== "pp" && x.text === text; }
  next() {
    const x = this.t[this.i++];
    if (x === undefined) throw new Error("unexpected end of body");
    return x;
  }
  expect(text) {
    const x = this.next();
    if (x.text !== text) throw new Error(`line ${x.line}: expected '${text}', found '${x.text}'`);
    return x;
  }
  source(from, to) { return this.ctx.src.slice(this.t[from].start, this.t[to - 1].end).replace(/\s+/g, " "); }

  // One mutant: its id, where it is and what it changes.
  mutant(op, line, original, mutated) {
    const id = this.ctx.nextId++;
    this.ctx.mutants.push({ id, file: this.ctx.file, line, op, original, mutated });
    return id;
  }
  // The node's text with its alternatives: (SNELL_MUT(a) ? altA : SNELL_MUT(b) ? altB : original).
  choose(alternatives, original) {
    if (!alternatives.length) return original;
    return `(${alternatives.map(([id, text]) => `SNELL_MUT(${id}) ? ${text} : `).join("")}${original})`;
  }

  block() {
    this.expect("{");
    const out = [];
    while (!this.at("}")) out.push(this.statement());
    this.expect("}");
    return `{\n${out.join("\n")}\n}`;
  }
  // A sub-statement always braced: a dropped statement becomes an if, which must not take an else.
  inner() {
    const s = this.statement();
    return s.startsWith("{") ? s : `{ ${s} }`;
  }
  isDeclaration() {
    let k = 0;
    while (this.peek(k)?.kind === "id" && QUALIFIERS.has(this.peek(k).text)) ++k;
    const a = this.peek(k), b = this.peek(k + 1);
    return a?.kind === "id" && b?.kind === "id";
  }
  declaration() {
    const parts = [];
    while (QUALIFIERS.has(this.peek().text)) parts.push(this.next().text);
    parts.push(this.next().text);  // the type
    const declarators = [];
    for (;;) {
      let d = this.next().text;
      if (this.at("[")) {  // an array size stays as written: it must be a constant
        const from = this.i;
        let depth = 0;
        do {
          const x = this.next();
          if (x.text === "[") ++depth;
          if (x.text === "]") --depth;
        } while (depth > 0);
        d += this.source(from, this.i);
      }
      if (this.at("=")) {
        this.next();
        d += ` = ${this.expression(2)}`;
      }
      declarators.push(d);
      if (!this.at(",")) break;
      this.next();
    }
    return `${parts.join(" ")} ${declarators.join(", ")}`;
  }
  statement() {
    const x = this.peek();
    if (x.kind === "pp") { this.next(); return `\n${x.text}\n`; }
    if (x.text === "{") return this.block();
    if (x.text === ";") { this.next(); return ";"; }
    if (x.text === "if") {
      this.next(); this.expect("(");
      const c = this.expression(0); this.expect(")");
      const a = this.inner();
      if (this.at("else")) { this.next(); return `if (${c}) ${a} else ${this.inner()}`; }
      return `if (${c}) ${a}`;
    }
    if (x.text === "for") {
      this.next(); this.expect("(");
      const init = this.at(";") ? "" : (this.isDeclaration() ? this.declaration() : this.expressionList());
      this.expect(";");
      const cond = this.at(";") ? "" : this.expression(0);
      this.expect(";");
      const step = this.at(")") ? "" : this.expressionList();
      this.expect(")");
      return `for (${init}; ${cond}; ${step}) ${this.inner()}`;
    }
    if (x.text === "while") {
      this.next(); this.expect("(");
      const c = this.expression(0); this.expect(")");
      return `while (${c}) ${this.inner()}`;
    }
    if (x.text === "do") {
      this.next();
      const body = this.inner();
      this.expect("while"); this.expect("(");
      const c = this.expression(0); this.expect(")"); this.expect(";");
      return `do ${body} while (${c});`;
    }
    if (x.text === "return") {
      this.next();
      if (this.at(";")) { this.next(); return "return;"; }
      const e = this.expression(0); this.expect(";");
      return `return ${e};`;
    }
    if (x.text === "break" || x.text === "continue") {
      this.next(); this.expect(";");
      const id = this.mutant("drop", x.line, `${x.text};`, "");
      return `if (!SNELL_MUT(${id})) { ${x.text}; }`;
    }
    if (x.text === "discard") { this.next(); this.expect(";"); return "discard;"; }
    if (this.isDeclaration()) {
      const d = this.declaration(); this.expect(";");
      return `${d};`;
    }
    const from = this.i;
    const e = this.expressionList();
    this.expect(";");
    const id = this.mutant("drop", x.line, `${this.source(from, this.i)}`, "");
    return `if (!SNELL_MUT(${id})) { ${e}; }`;
  }
  expressionList() {
    const parts = [this.expression(1)];
    while (this.at(",")) { this.next(); parts.push(this.expression(1)); }
    return parts.join(", ");
  }

  // Precedence climbing; returns the node's text with its alternatives. `minPrec`: 1 assignment, 2
  // conditional, 3 and up the binary operators.
  expression(minPrec) {
    const from = this.i;
    let left = this.unary();
    let leftInfo = this.lastInfo;
    for (;;) {
      const op = this.peek();
      if (!op || op.kind !== "op") break;
      if (ASSIGN.has(op.text) && minPrec <= 1) {
        this.next();
        const right = this.expression(1);
        left = `${left} ${op.text} ${right}`;
        leftInfo = null;
        continue;
      }
      if (op.text === "?" && minPrec <= 2) {
        this.next();
        const a = this.expression(1);
        this.expect(":");
        const b = this.expression(2);
        left = `(${left} ? ${a} : ${b})`;
        leftInfo = null;
        continue;
      }
      const prec = BINARY.get(op.text);
      if (prec === undefined || prec < Math.max(minPrec, 3)) break;
      this.next();
      const rightFrom = this.i;
      const right = this.expression(prec + 1);
      const rightInfo = this.lastInfo;
      const original = `(${left} ${op.text} ${right})`;
      const alts = [];
      const text = this.source(from, this.i);
      if (FLIP[op.text]) {
        alts.push([this.mutant("flip", op.line, text, `${op.text} -> ${FLIP[op.text]}`), `(${left} ${FLIP[op.text]} ${right})`]);
        // A literal compared against is a threshold: its 1-ulp (or, for an integer, 1) neighbour.
        for (const [info, side] of [[leftInfo, "left"], [rightInfo, "right"]]) {
          if (!info?.literal || !info.float) continue;  // an integer threshold's neighbour is int+1's mutant
          const moved = floatLiteral(ulpUp(floatOf(info.literal)));
          const mutated = side === "left" ? `(${info.sign}${moved} ${op.text} ${right})` : `(${left} ${op.text} ${info.sign}${moved})`;
          alts.push([this.mutant("ulp", op.line, text, `${info.sign}${info.literal} -> ${info.sign}${moved}`), mutated]);
        }
      }
      if (op.text === "-" || op.text === "/")
        alts.push([this.mutant("swap", op.line, text, `${this.source(rightFrom, this.i)} ${op.text} ${this.source(from, rightFrom - 1)}`),
          `(${right} ${op.text} ${left})`]);
      left = this.choose(alts, original);
      leftInfo = null;
    }
    this.lastInfo = leftInfo;
    return left;
  }
  unary() {
    const x = this.peek();
    if (x.kind === "op" && ["-", "+", "!", "~", "++", "--"].includes(x.text)) {
      this.next();
      const inner = this.unary();
      const info = this.lastInfo;
      this.lastInfo = info?.literal && x.text === "-" && !info.sign ? { ...info, sign: "-" } : null;
      // The literal's own alternatives already hold its sign's operand: -(1.1 x) is -x times 1.1.
      return `${x.text}${inner}`;
    }
    return this.postfix();
  }
  postfix() {
    let e = this.primary();
    let info = this.lastInfo;
    for (;;) {
      if (this.at("(")) {
        const callee = e;
        const line = this.peek().line;
        this.next();
        const args = [];
        while (!this.at(")")) {
          args.push(this.expression(1));
          if (this.at(",")) this.next();
        }
        this.expect(")");
        const original = `${callee}(${args.join(", ")})`;
        const alts = [];
        if (callee === "clamp" && args.length === 3) {
          alts.push([this.mutant("clamp", line, `clamp(..)`, "clamp(x, lo, hi) -> max(x, lo)"), `max(${args[0]}, ${args[1]})`]);
          alts.push([this.mutant("clamp", line, `clamp(..)`, "clamp(x, lo, hi) -> min(x, hi)"), `min(${args[0]}, ${args[2]})`]);
        }
        e = this.choose(alts, original);
        info = null;
        continue;
      }
      if (this.at("[")) {
        this.next();
        const idx = this.expression(0);
        this.expect("]");
        e = `${e}[${idx}]`;
        info = null;
        continue;
      }
      if (this.at(".")) {
        this.next();
        e = `${e}.${this.next().text}`;
        info = null;
        continue;
      }
      if (this.at("::")) {
        this.next();
        e = `${e}::${this.next().text}`;
        info = null;
        continue;
      }
      if (this.at("++") || this.at("--")) {
        e = `${e}${this.next().text}`;
        info = null;
        continue;
      }
      break;
    }
    this.lastInfo = info;
    return e;
  }
  primary() {
    const x = this.next();
    this.lastInfo = null;
    if (x.kind === "pp") throw new Error(`line ${x.line}: a preprocessor line inside an expression`);
    if (x.text === "(") {
      const e = this.expression(0);
      this.expect(")");
      return `(${e})`;
    }
    if (x.kind === "id") return x.text;
    if (x.kind === "num") {
      const isFloat = /[.eEfF]/.test(x.text) && !/^0[xX]/.test(x.text);
      this.lastInfo = { literal: x.text, float: isFloat, sign: "" };
      if (isFloat) {
        const v = floatOf(x.text);
        if (v === 0) return x.text;
        const id = this.mutant("10%", x.line, x.text, floatLiteral(v * 1.1));
        return this.choose([[id, floatLiteral(v * 1.1)]], x.text);
      }
      const unsigned = /[uU]$/.test(x.text);
      const v = Number(x.text.replace(/[uU]$/, ""));
      const up = `${v + 1}${unsigned ? "u" : ""}`;
      return this.choose([[this.mutant("int+1", x.line, x.text, up), up]], x.text);
    }
    throw new Error(`line ${x.line}: unexpected '${x.text}'`);
  }
}

// The schema of one file: every function body rewritten, every `#define NAME <float literal>` given its 10%
// alternative; ids from firstId on.
export function schemaOf(src, { file, firstId = 0 }) {
  const toks = tokenize(src);
  const ctx = { src, file, nextId: firstId, mutants: [] };
  const edits = [];  // [start, end, text]
  const unparsed = [];
  let depth = 0;
  for (let i = 0; i < toks.length; ++i) {
    const t = toks[i];
    if (t.kind === "pp") {
      const m = /^#\s*define\s+([A-Z0-9_]+)\s+(\d+\.\d*(?:[eE][+-]?\d+)?f|\d+\.\d*f?)\s*$/.exec(t.text);
      if (m && depth === 0) {
        const v = floatOf(m[2]);
        if (v !== 0) {
          const id = ctx.nextId++;
          ctx.mutants.push({ id, file, line: t.line, op: "10%", original: `#define ${m[1]} ${m[2]}`, mutated: floatLiteral(v * 1.1) });
          edits.push([t.start, t.end, `#define ${m[1]} (SNELL_MUT(${id}) ? ${floatLiteral(v * 1.1)} : ${m[2]})`]);
        }
      }
      continue;
    }
    if (t.text === "{" && depth === 0 && toks[i - 1]?.text === ")") {
      // A function body: find its end, parse it, keep the original on failure.
      let j = i, d = 0;
      do {
        if (toks[j].text === "{") ++d;
        if (toks[j].text === "}") --d;
        ++j;
      } while (d > 0 && j < toks.length);
      const saved = { nextId: ctx.nextId, count: ctx.mutants.length };
      const p = new Parser(toks.slice(i, j), ctx);
      let name = "?";
      for (let k = i - 1, paren = 0; k >= 0; --k) {
        if (toks[k].text === ")") ++paren;
        if (toks[k].text === "(") { if (--paren === 0) { name = toks[k - 1]?.text ?? "?"; break; } }
      }
      try {
        const body = p.block();
        if (p.i !== j - i) throw new Error("body not consumed");
        edits.push([t.start, toks[j - 1].end, body]);
      } catch (e) {
        ctx.nextId = saved.nextId;
        ctx.mutants.length = saved.count;
        unparsed.push(`${file}: ${name}: ${e.message}`);
      }
      i = j - 1;
      continue;
    }
    if (t.text === "{") ++depth;
    if (t.text === "}") --depth;
  }
  let text = src;
  for (const [s, e, r] of edits.sort((a, b) => b[0] - a[0])) text = text.slice(0, s) + r + text.slice(e);
  return { text, mutants: ctx.mutants, unparsed, nextId: ctx.nextId };
}
