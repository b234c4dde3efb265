--[[
docx-numbering.lua -- pandoc Lua filter for the Word (.docx) report.

Used by mechdesign.render.docx (pandoc 3 AST).  It

  * numbers figure captions "图 N  ..." (lang zh) / "Figure N: ..." (en) and
    captioned tables "表 N  ..." / "Table N: ..."; the number is a Word SEQ
    field (with the number already filled in), so Word's "Update Field" and
    "Insert Caption" continue the same sequence;
  * replaces references @fig:x / @tbl:x (also [@fig:x], -@fig:x for the bare
    number) by the same text "图 N" / "Figure N";
  * numbers every display equation ($$ ... $$): the equation stays a Word
    equation (OMML, made by pandoc from the TeX) and is laid out in a
    borderless three-column table  | | equation | (N) |;
  * converts image widths given in percent to centimetres of the text width;
  * puts a title block (student, student no., class, supervisor, date) under
    the title and subtitle, followed by a page break, then the table of contents
    (an empty TOC field; render/docx_toc.py writes its entries and page numbers) on a
    page of its own.

Metadata read: report-lang (else lang), labels.{student,student_id,class,teacher,date},
student, student_id, class, teacher, date, docx-text-width (twips), toc-title.
Styles used (defined in reference.docx; Word falls back to Normal if a
style is missing): Equation, Equation Number, Equation Table, Title Info,
Table Text (Table Text Small, Table Text Smaller: a table too wide for its numbers).
--]]

local stringify = pandoc.utils.stringify

local TEXT_WIDTH = 9070   -- twips; A4 with 2.5 cm margins (overridden by metadata)
local is_zh = true
local names               -- caption labels of the current language
local counters = { figure = 0, table = 0, equation = 0 }
local targets = {}        -- label -> { kind = "figure"|"table", n = N }

local NAMES = {
  zh = { figure = "图", table = "表", caption_sep = { " ", " " }, list_sep = "、", info_sep = "：" },
  en = { figure = "Figure", table = "Table", caption_sep = { ":", " " }, list_sep = ", ", info_sep = ": " },
}
-- SEQ field identifiers (Word's caption label names)
local SEQ = { zh = { figure = "图", table = "表" }, en = { figure = "Figure", table = "Table" } }

local function warn(msg)
  if pandoc.log and pandoc.log.warn then
    pandoc.log.warn(msg)
  else
    io.stderr:write("[WARNING] " .. msg .. "\n")
  end
end

local function xml_escape(s)
  return (s:gsub("&", "&amp;"):gsub("<", "&lt;"):gsub(">", "&gt;"):gsub('"', "&quot;"))
end

local function run_xml(text)
  return '<w:r><w:t xml:space="preserve">' .. xml_escape(text) .. "</w:t></w:r>"
end

-- A SEQ field whose current result is already n (Word shows it as is; F9 recomputes).
-- Written as a complex field (begin/instr/separate/result/end), as Word does:
-- readers that do not evaluate fields still show the result.
local function seq_xml(name, n)
  local function fld(kind) return '<w:r><w:fldChar w:fldCharType="' .. kind .. '" /></w:r>' end
  return fld("begin")
      .. '<w:r><w:instrText xml:space="preserve"> SEQ ' .. xml_escape(name)
      .. ' \\* ARABIC </w:instrText></w:r>'
      .. fld("separate")
      .. "<w:r><w:t>" .. tostring(n) .. "</w:t></w:r>"
      .. fld("end")
end

local function lang_key() return is_zh and "zh" or "en" end

-- "图 N" as inlines; with_field: the number as a SEQ field (captions only)
local function label_inlines(kind, n, with_field)
  local out = pandoc.Inlines { pandoc.Str(names[kind]), pandoc.Space() }
  if with_field then
    out:insert(pandoc.RawInline("openxml", seq_xml(SEQ[lang_key()][kind], n)))
  else
    out:insert(pandoc.Str(tostring(n)))
  end
  return out
end

-- Prefix "图 N  " / "Figure N: " to a caption (pandoc Caption object).
local function number_caption(caption, kind, n)
  local prefix = label_inlines(kind, n, true)
  local body = caption.long
  local first = body[1]
  if first and (first.t == "Plain" or first.t == "Para") and #first.content > 0 then
    -- zh: two spaces (about one ideographic space); en: ": "
    for _, piece in ipairs(names.caption_sep) do
      prefix:insert(piece == " " and pandoc.Space() or pandoc.Str(piece))
    end
    prefix:extend(first.content)
    first.content = prefix
  elseif first and (first.t == "Plain" or first.t == "Para") then
    first.content = prefix
  else
    body:insert(1, pandoc.Plain(prefix))
  end
  caption.long = body
  return caption
end

---------------------------------------------------------------------------
-- display equations

local function twips(x) return tostring(math.floor(x + 0.5)) end

local function equation_blocks(math_el, n)
  local side = TEXT_WIDTH * 0.1
  local mid = TEXT_WIDTH - 2 * side
  local no_borders = "<w:tblBorders>"
    .. '<w:top w:val="nil" /><w:left w:val="nil" /><w:bottom w:val="nil" />'
    .. '<w:right w:val="nil" /><w:insideH w:val="nil" /><w:insideV w:val="nil" />'
    .. "</w:tblBorders>"
  local function cell_pr(w)
    return '<w:tcPr><w:tcW w:w="' .. twips(w) .. '" w:type="dxa" /><w:vAlign w:val="center" /></w:tcPr>'
  end
  local open = "<w:tbl><w:tblPr>"
    .. '<w:tblStyle w:val="EquationTable" />'
    .. '<w:tblW w:w="5000" w:type="pct" /><w:jc w:val="center" />'
    .. no_borders
    .. '<w:tblLayout w:type="fixed" />'
    .. '<w:tblCellMar><w:top w:w="0" w:type="dxa" /><w:left w:w="0" w:type="dxa" />'
    .. '<w:bottom w:w="0" w:type="dxa" /><w:right w:w="0" w:type="dxa" /></w:tblCellMar>'
    .. '<w:tblLook w:val="0000" w:firstRow="0" w:lastRow="0" w:firstColumn="0" '
    .. 'w:lastColumn="0" w:noHBand="1" w:noVBand="1" />'
    .. "</w:tblPr><w:tblGrid>"
    .. '<w:gridCol w:w="' .. twips(side) .. '" /><w:gridCol w:w="' .. twips(mid) .. '" />'
    .. '<w:gridCol w:w="' .. twips(side) .. '" /></w:tblGrid>'
    .. "<w:tr><w:trPr><w:cantSplit /></w:trPr>"
    .. "<w:tc>" .. cell_pr(side)
    .. '<w:p><w:pPr><w:pStyle w:val="EquationNumber" /></w:pPr></w:p></w:tc>'
    .. "<w:tc>" .. cell_pr(mid)
  local close = "</w:tc><w:tc>" .. cell_pr(side)
    .. '<w:p><w:pPr><w:pStyle w:val="EquationNumber" /><w:jc w:val="right" /></w:pPr>'
    .. run_xml("(") .. seq_xml("Equation", n) .. run_xml(")")
    .. "</w:p></w:tc></w:tr></w:tbl>"
  return {
    pandoc.RawBlock("openxml", open),
    pandoc.Div({ pandoc.Para { math_el } }, { ["custom-style"] = "Equation" }),
    pandoc.RawBlock("openxml", close),
  }
end

local function is_display_math(el)
  return el.t == "Math" and el.mathtype == "DisplayMath"
end

local function is_blank(el)
  return el.t == "Space" or el.t == "SoftBreak" or el.t == "LineBreak"
end

-- Para/Plain containing display math -> text paragraphs and numbered equations.
local function split_display_math(block)
  local found = false
  for _, el in ipairs(block.content) do
    if is_display_math(el) then found = true; break end
  end
  if not found then return nil end
  local make = block.t == "Para" and pandoc.Para or pandoc.Plain
  local out = pandoc.Blocks {}
  local current = pandoc.Inlines {}
  local function flush()
    while #current > 0 and is_blank(current[1]) do current:remove(1) end
    while #current > 0 and is_blank(current[#current]) do current:remove(#current) end
    if #current > 0 then out:insert(make(current)) end
    current = pandoc.Inlines {}
  end
  for _, el in ipairs(block.content) do
    if is_display_math(el) then
      flush()
      counters.equation = counters.equation + 1
      out:extend(equation_blocks(el, counters.equation))
    else
      current:insert(el)
    end
  end
  flush()
  return out, false
end

---------------------------------------------------------------------------
-- figures, tables, images

local function percent_to_cm(value)
  local pct = value and tonumber(value:match("^%s*([%d%.]+)%%%s*$"))
  if not pct then return nil end
  return string.format("%.2fcm", pct / 100 * TEXT_WIDTH / 566.93)
end

local function fix_image(img)
  local width = percent_to_cm(img.attributes.width)
  if width then
    img.attributes.width = width
    if img.attributes.height and img.attributes.height:match("%%") then
      img.attributes.height = nil
    end
  end
  return img
end

local function figure_id(fig)
  if fig.identifier ~= "" then return fig.identifier end
  local id = ""
  fig:walk { Image = function(img) if id == "" then id = img.identifier end end }
  return id
end

local function wrap_cells(tbl, style)
  -- table text: its own paragraph style (small, single-spaced, no indent; smaller for a
  -- table too wide for its numbers at 10.5 pt, see set_widths).
  -- Properties of pandoc objects return copies: modify, then assign back.
  local function wrap_rows(rows)
    for r, row in ipairs(rows) do
      local cells = row.cells
      for c, cell in ipairs(cells) do
        if #cell.contents > 0 then
          -- (pandoc styles a bare Plain in a cell "Compact" whatever its Div says)
          local blocks = pandoc.Blocks(cell.contents):walk {
            Plain = function(plain) return pandoc.Para(plain.content) end,
          }
          cell.contents = { pandoc.Div(blocks, { ["custom-style"] = style }) }
          cells[c] = cell
        end
      end
      row.cells = cells
      rows[r] = row
    end
    return rows
  end
  local head = tbl.head
  head.rows = wrap_rows(head.rows)
  tbl.head = head
  local bodies = tbl.bodies
  for b, body in ipairs(bodies) do
    body.head = wrap_rows(body.head)
    body.body = wrap_rows(body.body)
    bodies[b] = body
  end
  tbl.bodies = bodies
  local foot = tbl.foot
  foot.rows = wrap_rows(foot.rows)
  tbl.foot = foot
  return tbl
end

-- Column widths from the cells' contents (pandoc leaves "natural" widths to the reader:
-- Word autofits, LibreOffice and WPS squeeze the columns). Half-width characters count 1,
-- CJK and full-width 2; TeX math counts about half its source length.
local function is_wide(c) return c >= 0x2E80 and c <= 0xFFEF end

local function text_len(s)
  local n = 0
  for _, c in utf8.codes(s) do
    n = n + (is_wide(c) and 2 or 1)
  end
  return n
end

-- Width (twips at 10.5 pt, 1 em = 210 twips) of one character of table text, after the
-- advance widths of Times (AFM, 1/1000 em; Liberation Serif has the same): CJK 1 em,
-- digits 0.5 em, "." "," ":" 0.25 em, "-" 0.33 em, capitals and m/w about 0.7–0.8 em.
local function char_twips(c)
  if is_wide(c) then return 212 end
  if c >= 0x30 and c <= 0x39 then return 106 end
  if c == 0x2E or c == 0x2C or c == 0x3A or c == 0x3B or c == 0x27 or c == 0x69
      or c == 0x6C or c == 0x7C or c == 0x21 then return 56 end
  if c == 0x2D or c == 0x2F or c == 0x28 or c == 0x29 then return 72 end
  if c == 0x6D or c == 0x77 or c == 0x4D or c == 0x57 then return 190 end
  if c >= 0x41 and c <= 0x5A then return 152 end
  return 112
end

-- Length (characters, as text_len) of a cell's text, and width (twips at 10.5 pt) of its
-- widest piece that no line may break: a number or word (a Str up to a space; a line may
-- break after "/" and around CJK characters), an inline formula (one object) or a word of code.
-- A cell of a single short Chinese word ("合格", "不合格", "结论": at most SHORT_CJK characters
-- and no space) is one piece too: Word would break it between its characters ("合" over "格").
local SHORT_CJK = 4

local function cell_measure(cell)
  local n, piece, widest, whole, spaced = 0, 0, 0, 0, false
  local function flush()
    widest = math.max(widest, piece)
    piece = 0
  end
  pandoc.Blocks(cell.contents):walk {
    Str = function(el)
      n = n + text_len(el.text)
      for _, c in utf8.codes(el.text) do
        whole = whole + char_twips(c)
        if is_wide(c) then
          flush(); piece = char_twips(c); flush()
        else
          piece = piece + char_twips(c)
          if c == 0x2F then flush() end
        end
      end
    end,
    Space = function() n = n + 1; spaced = true; flush() end,
    SoftBreak = flush,
    LineBreak = flush,
    Math = function(el)
      local len = math.ceil(text_len(el.text) / 2)
      n = n + len
      piece = piece + len * 112
      spaced = true
    end,
    -- code ("feed_verification"): Verbatim Char, Consolas 9 pt (reference.docx), 0.55 em a
    -- character = 99 twips (110 with some room); a line breaks only at its spaces
    Code = function(el)
      n = n + text_len(el.text)
      for _, c in utf8.codes(el.text) do
        if c == 0x20 then flush() else piece = piece + (is_wide(c) and 200 or 110) end
      end
    end,
  }
  flush()
  if not spaced and n <= 2 * SHORT_CJK then widest = math.max(widest, whole) end
  return n, widest
end

-- Table text sizes (half-points) and their paragraph styles (reference.docx): a table whose
-- numbers do not fit their columns at 10.5 pt is set at 9 pt, or 7.5 pt.
local TABLE_SIZES = { { 21, "Table Text" }, { 18, "Table Text Small" }, { 15, "Table Text Smaller" } }
local CELL_MARGINS = 216 + 30     -- left + right cell margins of the Table style, and a little

-- Sets the relative column widths; returns the paragraph style of the table's text.
local function set_widths(tbl)
  local ncol = #tbl.colspecs
  local longest, widest = {}, {}
  for c = 1, ncol do longest[c] = 2; widest[c] = 0 end
  local function scan(rows)
    for _, row in ipairs(rows) do
      for c, cell in ipairs(row.cells) do
        if c <= ncol and cell.col_span == 1 then
          local n, w = cell_measure(cell)
          longest[c] = math.max(longest[c], n)
          widest[c] = math.max(widest[c], w)
        end
      end
    end
  end
  scan(tbl.head.rows)
  for _, body in ipairs(tbl.bodies) do scan(body.head); scan(body.body) end
  local char, pad = 118, 300          -- twips per half-width character at 10.5 pt; cell margins
  local natural, least, style
  for _, size in ipairs(TABLE_SIZES) do
    local scale = size[1] / 21
    natural, least = {}, {}
    local sum_least = 0
    for c = 1, ncol do
      least[c] = widest[c] * scale + CELL_MARGINS
      natural[c] = math.max(math.min(longest[c], 40) * char * scale + pad, least[c])
      sum_least = sum_least + least[c]
    end
    style = size[2]
    if sum_least <= TEXT_WIDTH then break end
  end
  local sum_natural, sum_least = 0, 0
  for c = 1, ncol do
    sum_natural = sum_natural + natural[c]
    sum_least = sum_least + least[c]
  end
  local width = {}
  for c = 1, ncol do
    if sum_natural <= TEXT_WIDTH then
      width[c] = natural[c]
    elseif sum_least < TEXT_WIDTH then
      -- every column keeps its widest number; the rest of the width goes by natural width
      local k = (TEXT_WIDTH - sum_least) / (sum_natural - sum_least)
      width[c] = least[c] + (natural[c] - least[c]) * k
    else
      width[c] = least[c] * TEXT_WIDTH / sum_least
    end
  end
  local specs = tbl.colspecs
  for c = 1, ncol do
    specs[c] = { specs[c][1], width[c] / TEXT_WIDTH }
  end
  tbl.colspecs = specs
  return tbl, style
end

local number_pass = {
  traverse = "topdown",
  Figure = function(fig)
    counters.figure = counters.figure + 1
    local id = figure_id(fig)
    if id ~= "" then targets[id] = { kind = "figure", n = counters.figure } end
    fig.caption = number_caption(fig.caption, "figure", counters.figure)
    return fig:walk { Image = fix_image }, false
  end,
  Table = function(tbl)
    if stringify(tbl.caption.long) ~= "" then
      counters.table = counters.table + 1
      if tbl.identifier ~= "" then
        targets[tbl.identifier] = { kind = "table", n = counters.table }
      end
      tbl.caption = number_caption(tbl.caption, "table", counters.table)
    end
    -- display math inside table cells stays unnumbered (no nested tables)
    local sized, style = set_widths(tbl:walk { Image = fix_image })
    return wrap_cells(sized, style), false
  end,
  Para = split_display_math,
  Plain = split_display_math,
  Image = fix_image,
}

---------------------------------------------------------------------------
-- references

local function utf8_first(s)
  for _, c in utf8.codes(s) do return c end
end

local function utf8_last(s)
  local last
  for _, c in utf8.codes(s) do last = c end
  return last
end

local function is_cjk(c)
  return c ~= nil and ((c >= 0x3000 and c <= 0x303F) or (c >= 0x3400 and c <= 0x9FFF)
    or (c >= 0xF900 and c <= 0xFAFF) or (c >= 0xFF00 and c <= 0xFFEF))
end

local function cjk_end(el) return el and el.t == "Str" and is_cjk(utf8_last(el.text)) end
-- a CJK punctuation mark (、，。：；（）…): no space before it
local function cjk_punct_start(el)
  local c = el and el.t == "Str" and utf8_first(el.text)
  return c and ((c >= 0x3000 and c <= 0x303F) or (c >= 0xFF00 and c <= 0xFFEF))
end

-- Inlines replacing a Cite whose keys are all figure/table labels, else nil.
local function reference_inlines(cite)
  local out = pandoc.Inlines {}
  for i, citation in ipairs(cite.citations) do
    local target = targets[citation.id]
    if not target then
      if citation.id:match("^fig:") or citation.id:match("^tbl:") then
        warn("docx: unknown reference @" .. citation.id)
      end
      return nil
    end
    if i > 1 then out:insert(pandoc.Str(names.list_sep)) end
    if #citation.prefix > 0 then
      out:extend(citation.prefix)
      out:insert(pandoc.Space())
    end
    if citation.mode == "SuppressAuthor" then
      out:insert(pandoc.Str(tostring(target.n)))
    else
      out:extend(label_inlines(target.kind, target.n, false))
    end
    if #citation.suffix > 0 then out:extend(citation.suffix) end
  end
  return out
end

local function resolve_references(inlines)
  local out = pandoc.Inlines {}
  local changed = false
  local i = 1
  while i <= #inlines do
    local el = inlines[i]
    local replacement = el.t == "Cite" and reference_inlines(el) or nil
    if replacement then
      changed = true
      -- Chinese: no space between a CJK character and the reference
      if #out >= 2 and out[#out].t == "Space" and cjk_end(out[#out - 1]) then
        out:remove(#out)
      end
      out:extend(replacement)
      -- after the number: a space before a Chinese word ("由图 6 量得", as the PDF sets the
      -- number apart on both sides: typst's CJK–Latin spacing), none before a punctuation mark
      if inlines[i + 1] and inlines[i + 1].t == "Space" and cjk_punct_start(inlines[i + 2]) then
        i = i + 1
      end
    else
      out:insert(el)
    end
    i = i + 1
  end
  if changed then return out end
  return nil
end

---------------------------------------------------------------------------
-- title block

local INFO_KEYS = { "student", "student_id", "class", "teacher", "date", "group" }
local DEFAULT_LABELS = {
  zh = { student = "姓名", student_id = "学号", class = "班级", teacher = "指导教师", date = "日期",
         group = "分组" },
  en = { student = "Name", student_id = "Student No.", class = "Class", teacher = "Supervisor",
         date = "Date", group = "Data group" },
}

local function title_block(meta)
  local labels = meta.labels or {}
  local blocks = pandoc.Blocks {}
  for _, key in ipairs(INFO_KEYS) do
    local value = meta[key] and stringify(meta[key]) or ""
    if value ~= "" then
      local label = labels[key] and stringify(labels[key]) or DEFAULT_LABELS[lang_key()][key]
      local inlines = pandoc.Inlines { pandoc.Str(label .. names.info_sep) }
      inlines:extend(pandoc.Inlines(value))
      blocks:insert(pandoc.Div({ pandoc.Para(inlines) }, { ["custom-style"] = "Title Info" }))
    end
  end
  local has_title = meta.title and stringify(meta.title) ~= ""
  if #blocks > 0 or has_title then
    blocks:insert(pandoc.RawBlock("openxml", '<w:p><w:r><w:br w:type="page" /></w:r></w:p>'))
  end
  return blocks
end

---------------------------------------------------------------------------
-- table of contents: after the title page, on a page of its own (pandoc's --toc would put
-- it between the subtitle and the title block); an empty TOC field, as pandoc writes it,
-- that render/docx_toc.py replaces by the entries with their page numbers (and the page
-- break below by w:pageBreakBefore on the body's first heading)

local function contents_blocks(meta)
  local title = meta["toc-title"] and stringify(meta["toc-title"]) or ""
  local heading = ""
  if title ~= "" then
    heading = '<w:p><w:pPr><w:pStyle w:val="TOCHeading" /></w:pPr>' .. run_xml(title) .. "</w:p>"
  end
  local field = '<w:p><w:r><w:fldChar w:fldCharType="begin" w:dirty="true" />'
    .. '<w:instrText xml:space="preserve">TOC \\o &quot;1-3&quot; \\h \\z \\u</w:instrText>'
    .. '<w:fldChar w:fldCharType="separate" /><w:fldChar w:fldCharType="end" /></w:r></w:p>'
  return {
    pandoc.RawBlock("openxml", "<w:sdt><w:sdtPr><w:docPartObj>"
      .. '<w:docPartGallery w:val="Table of Contents" /><w:docPartUnique />'
      .. "</w:docPartObj></w:sdtPr><w:sdtContent>" .. heading .. field
      .. "</w:sdtContent></w:sdt>"),
    pandoc.RawBlock("openxml", '<w:p><w:r><w:br w:type="page" /></w:r></w:p>'),
  }
end

---------------------------------------------------------------------------

function Pandoc(doc)
  local meta = doc.meta
  local lang = meta["report-lang"] or meta.lang
  lang = lang and stringify(lang) or "zh"
  is_zh = lang:lower():match("^zh") ~= nil
  names = NAMES[lang_key()]
  local width = meta["docx-text-width"] and tonumber(stringify(meta["docx-text-width"]))
  if width and width > 0 then TEXT_WIDTH = width end

  doc = doc:walk(number_pass)
  doc = doc:walk { Inlines = resolve_references }

  local front = title_block(meta)
  front:extend(contents_blocks(meta))
  front:extend(doc.blocks)
  doc.blocks = front
  -- the date is shown in the title block, not as pandoc's "Date" paragraph
  doc.meta.date = nil
  return doc
end
