"""A number never parted from its unit at a line end, in the PDF and in Word.

The report's Markdown writes a value with its unit as words ("α5 = -4.27 rad/s²",
"n = 1450 r/min"); a line may break at either space. :data:`LUA_FILTER` is a pandoc Lua
filter, run by both conversions (Markdown → typst, :mod:`.pdf`; Markdown → docx,
:mod:`.docx`), that turns the space between a number and the unit word after it into a
no-break space (U+00A0: pandoc's typst writer writes it as ``~``, Word keeps the character),
and likewise the space after a relation sign ("=", "≈", "≤", "≥") before a number, the space
before a relation sign written alone (the symbol stays with its "="), and the
spaces around "×" between two numbers ("1.4 × 10⁻¹⁴ mm"). For typst, which breaks an inline
formula after its relation ("$R_{BV} = -1978.4$ N" as "R_BV =" | "−1978.4 N"), a short
inline formula holding a relation is set in a box (``#box($…$);``), unbroken (a list of
relations, "$C_v = 2.000, C_a = 4.000$", item by item: a line may break after a comma); in a Chinese
report's paragraphs ``#run-break(n);`` marks where a line may break before an unbreakable run of
six characters or more (templates/report.typ ends the line there unjustified when the run
went to the next line: justified, its Chinese characters stood apart). It works on pandoc's document
tree, so formulas, code blocks and file names are never touched; the Markdown itself
(report.md) stays as written.
"""
from __future__ import annotations

#: The unit words a number may be followed by (a word starting with one of them and going
#: on with no letter or digit: "mm/s²", "kN·m" and "r/min" before a full-width comma count,
#: "steps" does not).
UNITS = ("mm", "m", "μm", "s", "min", "h", "N", "kN", "MN", "W", "kW", "J", "kJ", "kg", "g",
         "t", "rad", "rpm", "r/min", "°", "%", "Pa", "kPa", "MPa", "GPa", "Hz")

#: Signs after which the number stays on the same line.
RELATIONS = ("=", "≈", "≤", "≥", "<", ">", "→")


def _lua_list(words) -> str:
    return "{" + ", ".join('"' + w.replace("\\", "\\\\").replace('"', '\\"') + '"'
                           for w in words) + "}"


LUA_FILTER = r"""
local UNITS = @UNITS@
local RELATIONS = @RELATIONS@
local NBSP = utf8.char(0x00A0)
-- superscript digits and minus (10⁻¹⁴), as UTF-8 byte strings
local SUPERSCRIPTS = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹", "⁻"}

local function ends_with_number(t)
  if t:match("%d$") then return true end
  for _, s in ipairs(SUPERSCRIPTS) do
    if #t > #s and t:sub(-#s) == s then
      local head = t:sub(1, -#s - 1)
      return ends_with_number(head)
    end
  end
  return false
end

local function starts_with_number(t)
  -- "5", "-4.27", "−4.27" (U+2212), "+3", "(12"
  return t:match("^[-+(]?%d") ~= nil or t:match("^\226\136\146%d") ~= nil
end

local function starts_with_unit(t)
  for _, u in ipairs(UNITS) do
    if t:sub(1, #u) == u then
      local rest = t:sub(#u + 1)
      if rest == "" or not rest:match("^[%w_]") then return true end
    end
  end
  return false
end

local function text_of(el)
  if el == nil then return nil end
  if el.t == "Str" then return el.text end
  if el.t == "Math" and el.mathtype == "InlineMath" then return el.text end
  return nil
end

local function joined(a, b)
  if a == nil or b == nil then return false end
  if ends_with_number(a) and starts_with_unit(b) then return true end
  -- a relation sign written alone stays with the symbol before it ("ω₆" | "= 0 rad/s":
  -- lines break after a relation, never before it)
  for _, r in ipairs(RELATIONS) do
    if b == r then return true end
  end
  if starts_with_number(b) then
    -- "=" alone, or ending a word (a closing full-width parenthesis and "=")
    for _, r in ipairs(RELATIONS) do
      if #a >= #r and a:sub(-#r) == r then return true end
    end
  end
  return false
end

local function times(inlines, i)
  -- the spaces around "×" between two numbers: 1.4 × 10⁻¹⁴
  local a, b, c = text_of(inlines[i - 1]), text_of(inlines[i + 1]), text_of(inlines[i + 3])
  return b == "×" and a ~= nil and ends_with_number(a) and c ~= nil and starts_with_number(c)
         and inlines[i + 2] ~= nil and inlines[i + 2].t == "Space"
end

local WJ = utf8.char(0x2060)
local function glued_relation(t)
  -- "(link 4)=" written with full-width brackets, ending a word: typst may break between
  -- the closing full-width bracket (U+FF09) and the "=" (the value then starts its line
  -- with "="); a word joiner keeps them together (only after U+FF09: other text, the
  -- user's "<label>" say, is left as written)
  for _, r in ipairs(RELATIONS) do
    if #t > #r + 2 and t:sub(-#r) == r and t:sub(-#r - 3, -#r - 1) == "\239\188\137" then
      return t:sub(1, -#r - 1) .. WJ .. r
    end
  end
  return nil
end

-- a unit with a solidus written as a word ("rad/s;", "N/mm", "(mm/s²)"): typst may break a
-- line after the "/" ("rad/" | "s", page review 47); in the PDF the word is set in a box,
-- unbroken (a box, not a word joiner: the PDF's text stays "rad/s")
local UNIT_TAILS = {"²", "³", "⁻", "¹", "·"}
local FULL_COMMA = utf8.char(0xFF0C)
local function slashed_unit(t)
  -- the unit at the start of ``t`` with the punctuation after it, and the rest
  -- ("r/min" + full-width comma + Chinese text: the unit and comma, the text), or nil
  if #t > 40 then return nil end
  local u = t:match("^%(?%a+/[%a/]*")
  if u == nil then return nil end
  local head = u:match("^%(?(%a+)/")
  local known = head == "r" and u:match("^%(?r/min") ~= nil
  for _, w in ipairs(UNITS) do
    if head == w then known = true end
  end
  if not known then return nil end
  local rest = t:sub(#u + 1)
  local moved = true
  while moved do
    moved = false
    for _, s in ipairs(UNIT_TAILS) do
      if rest:sub(1, #s) == s then
        u, rest, moved = u .. s, rest:sub(#s + 1), true
      end
    end
  end
  local p = rest:match("^[%)%.,;:]*")
  if rest:sub(#p + 1, #p + 3) == FULL_COMMA then p = p .. FULL_COMMA end
  return u .. p, rest:sub(#p + 1)
end

local function boxed_units(inlines)
  local out, changed = {}, false
  for _, el in ipairs(inlines) do
    local u, rest = nil, nil
    if el.t == "Str" then u, rest = slashed_unit(el.text) end
    if u ~= nil then
      out[#out + 1] = pandoc.RawInline("typst", "#box[")
      out[#out + 1] = pandoc.Str(u)
      out[#out + 1] = pandoc.RawInline("typst", "];")
      if rest ~= "" then out[#out + 1] = pandoc.Str(rest) end
      changed = true
    else
      out[#out + 1] = el
    end
  end
  if changed then return out end
  return nil
end

-- a quantity's symbol written as a word before its relation ("K = 1.05", "(φ = 0.0°)") is
-- set as a formula, italic as in the equations (ISO 80000-1: quantity symbols italic);
-- a letter that ends a word ("ab", "μφ", "2z") is left alone
local GREEK = {}
for _, c in utf8.codes("αβγδεζηθικλμνξπρστυφχψωΓΔΘΛΞΠΣΦΨΩ") do GREEK[utf8.char(c)] = true end

local function symbol_split(t)
  local last = utf8.offset(t, -1)
  if last == nil then return nil end
  local letter, prefix = t:sub(last), t:sub(1, last - 1)
  if not (letter:match("^[A-Za-z]$") or GREEK[letter]) then return nil end
  if prefix ~= "" then
    local p = utf8.offset(prefix, -1)
    if p == nil then return nil end
    local before = prefix:sub(p)
    if before:match("^[%w_$\\%-+*/^.]$") or GREEK[before] or before == "\226\136\146" then
      return nil
    end
  end
  return prefix, letter
end

local function italic_symbols(inlines)
  local out, changed = {}, false
  for i = 1, #inlines do
    local el, rel = inlines[i], inlines[i + 2]
    local done = false
    if el.t == "Str" and inlines[i + 1] ~= nil and inlines[i + 1].t == "Space"
       and rel ~= nil and rel.t == "Str" then
      local is_rel = false
      for _, r in ipairs(RELATIONS) do
        if rel.text == r then is_rel = true end
      end
      -- a unit after a value is no symbol ("$T_c = 0.9983$ N·m ≤ …", "48 000 h → 6311"
      -- set "N·𝑚", "ℎ": page review 41)
      local before = inlines[i - 1] ~= nil and inlines[i - 1].t == "Space" and text_of(inlines[i - 2]) or nil
      if is_rel and before ~= nil and ends_with_number(before) and starts_with_unit(el.text) then
        is_rel = false
      end
      if is_rel then
        local prefix, letter = symbol_split(el.text)
        if letter ~= nil then
          if prefix ~= "" then out[#out + 1] = pandoc.Str(prefix) end
          out[#out + 1] = pandoc.Math("InlineMath", letter)
          changed, done = true, true
        end
      end
    end
    -- a lone lowercase or Greek letter between spaces (the ram's displacement "s" in a
    -- Chinese sentence): a
    -- symbol, unless it is a unit after a number or "/" ("5 s", "/ m") or the English
    -- article "a"; capitals stay text (belt sections "A", "V"), and so does a letter alone
    -- in a table cell or at a line's end (a unit column's "s", "h")
    if not done and el.t == "Str" and (el.text:match("^[b-z]$") or GREEK[el.text])
       and inlines[i - 1] ~= nil and inlines[i - 1].t == "Space"
       and inlines[i + 1] ~= nil and inlines[i + 1].t == "Space"
       and not (text_of(inlines[i - 2]) ~= nil and (ends_with_number(text_of(inlines[i - 2]))
                                                    or text_of(inlines[i - 2]):match("/$"))) then
      out[#out + 1] = pandoc.Math("InlineMath", el.text)
      changed, done = true, true
    end
    if not done then out[#out + 1] = el end
  end
  if changed then return out end
  return nil
end

local function Inlines(inlines)
  local changed = false
  local italic = italic_symbols(inlines)
  if italic ~= nil then
    inlines, changed = italic, true
  end
  if FORMAT:match("typst") then
    for i = 1, #inlines do
      local el = inlines[i]
      if el.t == "Str" then
        local g = glued_relation(el.text)
        if g ~= nil then
          inlines[i] = pandoc.Str(g)
          changed = true
        end
      end
    end
  end
  for i = 2, #inlines - 1 do
    local el = inlines[i]
    if el.t == "Space" then
      local prev, next = inlines[i - 1], inlines[i + 1]
      local a, b = text_of(prev), text_of(next)
      -- a relation sign or unit written as text; a number may end a formula ($h = 14.9$ mm)
      if (prev.t == "Str" or next.t == "Str") and joined(a, b) then
        inlines[i] = pandoc.Str(NBSP)
        changed = true
      elseif times(inlines, i) then
        inlines[i] = pandoc.Str(NBSP)
        inlines[i + 2] = pandoc.Str(NBSP)
        changed = true
      end
    end
  end
  if FORMAT:match("typst") then
    local b = boxed_units(inlines)
    if b ~= nil then
      inlines, changed = b, true
    end
  end
  if changed then return inlines end
  return nil
end

-- typst breaks an inline formula after a relation ("R_BV =" | "-1978.4"): in the PDF a
-- short one with a relation is set in a box, unbroken (";" ends the embedded code, so a
-- "(" or "[" after it stays text)
local RELATION_TEX = {"=", "<", ">", "\\approx", "\\le", "\\ge", "\\ne"}

local function has_relation(t)
  for _, r in ipairs(RELATION_TEX) do
    if t:find(r, 1, true) then return true end
  end
  return false
end

local function list_items(t)
  -- a list of relations written as one formula ("C_v = 2.000, C_a = 4.000, C_j = \infty"):
  -- its items, split at the commas outside braces and brackets, when every item holds a
  -- relation (else nil)
  local items, depth, from = {}, 0, 1
  for i = 1, #t do
    local c = t:sub(i, i)
    if c == "{" or c == "(" or c == "[" then depth = depth + 1
    elseif c == "}" or c == ")" or c == "]" then depth = depth - 1
    elseif c == "," and depth == 0 and t:sub(i + 1, i + 1) == " " then
      items[#items + 1] = t:sub(from, i - 1)
      from = i + 2
    end
  end
  if #items == 0 then return nil end
  items[#items + 1] = t:sub(from)
  for _, item in ipairs(items) do
    if not has_relation(item) then return nil end
  end
  return items
end

local function boxed(el)
  if not FORMAT:match("typst") or el.mathtype ~= "InlineMath" or #el.text > 80 then
    return nil
  end
  if not has_relation(el.text) then return nil end
  -- a list of relations is boxed item by item: a line may break after each comma (one box
  -- for the whole list left the line before it with 8-11 pt word spaces, shaper en)
  local items = list_items(el.text)
  if items == nil then
    return {pandoc.RawInline("typst", "#box("), el, pandoc.RawInline("typst", ");")}
  end
  local out = {}
  for k, item in ipairs(items) do
    out[#out + 1] = pandoc.RawInline("typst", "#box(")
    out[#out + 1] = pandoc.Math("InlineMath", item)
    out[#out + 1] = pandoc.RawInline("typst", ");")
    if k < #items then
      out[#out + 1] = pandoc.Str(",")
      out[#out + 1] = pandoc.Space()
    end
  end
  return out
end

-- "min" and "max" in a subscript are words, set upright as in the textbook (γ_min, s_max):
-- "_{min}", "_{min,1}", "_{E,max}" become "\\min", which both writers set upright
local UPRIGHT_WORDS = {"min", "max"}

local function upright_subscripts(el)
  local t, n = el.text, 0
  for _, w in ipairs(UPRIGHT_WORDS) do
    local c
    t, c = t:gsub("_{" .. w .. "([},])", "_{\\" .. w .. "%1")
    n = n + c
    t, c = t:gsub(",(" .. w .. ")}", ",\\%1}")
    n = n + c
  end
  if n == 0 then return nil end
  el.text = t
  return el
end

-- zh: a line that an unbreakable run does not fit (a boxed formula, "$ΔW$ = 3499.5 J" held
-- together by no-break spaces, a long Latin word) ends short instead of spreading its
-- characters apart: "#run-break(n);" (templates/report.typ) goes where a line may break before
-- such a run. Only before a run of at least RUN_MIN characters: a shorter one leaves a gap
-- too small to matter.
local RUN_MIN = 6
-- the opening brackets and quotes: full-width parenthesis, curly quotes, book-title and
-- corner brackets (as code points: no Chinese literal in the code)
local OPENING = {utf8.char(0xFF08), utf8.char(0x201C), utf8.char(0x2018), utf8.char(0x300A),
                 utf8.char(0x300C), utf8.char(0x300E), utf8.char(0x3010), utf8.char(0x3008)}

local function has_cjk(t)
  for _, c in utf8.codes(t) do
    if (c >= 0x3000 and c <= 0x9FFF) or (c >= 0xFF00 and c <= 0xFFEF) then return true end
  end
  return false
end

local function opened_latin(t)
  -- a full-width opening bracket before a Latin word: "(OUTLINE)" in full-width brackets
  for _, o in ipairs(OPENING) do
    if t:sub(1, #o) == o and t:sub(#o + 1):match("^[%w]") then return true end
  end
  return false
end

local function run_length(inlines, i)
  -- characters of the unbreakable run from inlines[i]: up to a space or a Chinese character
  -- (a full-width opening bracket before it counts)
  local n = 0
  for j = i, #inlines do
    local el = inlines[j]
    if el.t == "Math" then n = n + utf8.len(el.text)
    elseif el.t == "Str" then
      local t = el.text
      if j == i and opened_latin(t) then
        n = n + 2
        t = t:sub(utf8.offset(t, 2))
      end
      for _, c in utf8.codes(t) do
        if (c >= 0x3000 and c <= 0x9FFF) or (c >= 0xFF00 and c <= 0xFFEF) then return n end
        n = n + 1
      end
    elseif el.t == "RawInline" then
    else return n end
  end
  return n
end

local function may_break_before(prev)
  -- a Space, or a Chinese character or closing punctuation ends the inline before
  if prev == nil then return false end
  if prev.t == "Space" then return true end
  if prev.t ~= "Str" then return false end
  local last = utf8.offset(prev.text, -1)
  if last == nil then return false end
  local c = prev.text:sub(last)
  for _, o in ipairs(OPENING) do
    if c == o then return false end
  end
  return has_cjk(c)
end

local function is_cjk_code(c)
  return (c >= 0x3000 and c <= 0x9FFF) or (c >= 0xFF00 and c <= 0xFFEF)
end

local function is_opening(ch)
  for _, o in ipairs(OPENING) do
    if ch == o then return true end
  end
  return false
end

local function starts_run(el)
  return el ~= nil and ((el.t == "Math" and el.mathtype == "InlineMath")
    or (el.t == "RawInline" and el.text == "#box(")
    or (el.t == "Str" and (el.text:match("^[%w%-+(]") ~= nil or opened_latin(el.text))))
end

local function cuts_in(inlines, i)
  -- byte offsets inside the word inlines[i] where a line may break before a long run: after
  -- a Chinese character (not an opening bracket), before a Latin run (a Chinese word, then "(OUTLINE)" in full-width brackets)
  -- or before an opening bracket that ends the word and a run after it (a word, then a
  -- full-width bracket and "$L = …$")
  local t, cuts = inlines[i].text, {}
  local chars = {}
  for pos, c in utf8.codes(t) do chars[#chars + 1] = {pos, c} end
  for k = 2, #chars do
    local a = utf8.char(chars[k - 1][2])
    local pos = chars[k][1]
    if is_cjk_code(chars[k - 1][2]) and not is_opening(a) then
      local rest = t:sub(pos)
      if rest:match("^[%w]") or opened_latin(rest) then
        local n, reached = 0, true
        local body = rest
        if opened_latin(rest) then n = 2; body = rest:sub(utf8.offset(rest, 2)) end
        for _, c in utf8.codes(body) do
          if is_cjk_code(c) then reached = false; break end
          n = n + 1
        end
        if reached then n = n + run_length(inlines, i + 1) end
        if n >= RUN_MIN then cuts[#cuts + 1] = {pos, n} end
      elseif k == #chars and is_opening(rest) and starts_run(inlines[i + 1])
             and run_length(inlines, i + 1) + 2 >= RUN_MIN then
        cuts[#cuts + 1] = {pos, run_length(inlines, i + 1) + 2}
      end
    end
  end
  return cuts
end

local function run_breaks(para)
  local inlines = para.content
  local out, changed = {}, false
  -- the mark carries the run's length in characters (typst's run-break estimates its width)
  local MARK = function(n) return pandoc.RawInline("typst", "#run-break(" .. n .. ");") end
  for i = 1, #inlines do
    local el = inlines[i]
    local lone_opening = el.t == "Str" and is_opening(el.text) and starts_run(inlines[i + 1])
      and run_length(inlines, i + 1) + 2 >= RUN_MIN
    if may_break_before(inlines[i - 1])
       and (lone_opening or (starts_run(el) and run_length(inlines, i) >= RUN_MIN)) then
      out[#out + 1] = MARK(lone_opening and run_length(inlines, i + 1) + 2 or run_length(inlines, i))
      changed = true
    end
    if el.t == "Str" then
      local cuts, from = cuts_in(inlines, i), 1
      for _, cut in ipairs(cuts) do
        local pos = cut[1]
        out[#out + 1] = pandoc.Str(el.text:sub(from, pos - 1))
        out[#out + 1] = MARK(cut[2])
        from = pos
      end
      if #cuts > 0 then
        el = pandoc.Str(el.text:sub(from))
        changed = true
      end
    end
    out[#out + 1] = el
  end
  if changed then return pandoc.Para(out) end
  return nil
end

local function run_breaks_in(doc)
  -- zh reports (the lang of the metadata), paragraphs only: never in a table's cells (their
  -- columns are measured unbroken), a caption or a heading (not justified)
  if not FORMAT:match("typst") then return nil end
  local lang = doc.meta.lang and pandoc.utils.stringify(doc.meta.lang) or ""
  if not lang:match("^zh") then return nil end
  return doc:walk({ Para = run_breaks })
end

return {
  { Math = upright_subscripts },
  { Inlines = Inlines },
  { Math = boxed },
  { Pandoc = run_breaks_in },
}
""".replace("@UNITS@", _lua_list(UNITS)).replace("@RELATIONS@", _lua_list(RELATIONS))
