-- End-to-end test of the RAPID plugin in headless Neovim (run by run.sh).
-- What Neovim shows is compared with what the rapid binary itself says
-- (`rapid check --format json`, `rapid builtins NAME`), not with copies.
-- Prints one line per check and "N passed, N failed"; exits non-zero on failure.
local TIMEOUT = tonumber(vim.env.RAPID_E2E_TIMEOUT_MS or '30000')
local rapid_bin = assert(vim.env.RAPID_BIN, 'RAPID_BIN')
local ws = assert(vim.env.RAPID_WS, 'RAPID_WS')
local log_path = vim.env.RAPID_NVIM_LOG

local passed, failed = 0, 0
local log_lines = {}

local function say(line)
  io.stdout:write(line .. '\n')
  table.insert(log_lines, line)
end

local function check(name, fn)
  local ok, err = xpcall(fn, debug.traceback)
  if ok then
    passed = passed + 1
    say('ok - ' .. name)
  else
    failed = failed + 1
    say('FAILED - ' .. name .. ': ' .. tostring(err))
  end
end

local function finish()
  say(('%d passed, %d failed'):format(passed, failed))
  if log_path then
    vim.fn.writefile(log_lines, log_path)
  end
  vim.cmd((failed == 0 and passed > 0) and 'qall!' or 'cquit! 1')
end

local function run(cmd)
  local r = vim.system(cmd, { text = true }):wait()
  return r.stdout or '', r.code, r.stderr or ''
end

local function expect(cond, fmt, ...)
  if not cond then
    error(fmt:format(...), 2)
  end
end

--- Text of an LSP hover/markup result.
local function markup_text(contents)
  if type(contents) == 'string' then
    return contents
  end
  if contents.value then
    return contents.value
  end
  local parts = {}
  for _, c in ipairs(contents) do
    table.insert(parts, type(c) == 'string' and c or c.value)
  end
  return table.concat(parts, '\n')
end

-- ------------------------------------------------------------ expectations
local main_path = ws .. '/MainModule.mod'
local lines = vim.fn.readfile(main_path)
local function line_of(needle)
  for i, l in ipairs(lines) do
    if l:find(needle, 1, true) then
      return i - 1, l -- 0-based
    end
  end
  error('no line with ' .. needle)
end

local check_json = run({ rapid_bin, 'check', ws, '--format', 'json' })
local expected = {}
local cell_expected = {}
for _, d in ipairs(vim.json.decode(check_json)) do
  if d.severity == 'error' and vim.fs.basename(d.file) == 'MainModule.mod' then
    table.insert(expected, d)
  elseif vim.fs.basename(d.file) == 'Cell.sys' then
    table.insert(cell_expected, d)
  end
end
local function signature(name)
  local text, code, err = run({ rapid_bin, 'builtins', name })
  assert(code == 0, 'rapid builtins ' .. name .. ': ' .. err)
  return vim.split(text, '\n')[1]
end
local wait_time_signature = signature('WaitTime')
local movel_signature = signature('MoveL')
-- the optional arguments of MoveL that may follow its last required one
-- (Tool): what completion offers after `tool\`
local movel_optionals = {}
for param in (movel_signature:match('%((.*)%)') or ''):gmatch('[^,|]+') do
  param = vim.trim(param)
  local name = param:gsub('{.-}', ''):match('([%a_][%w_]*)%s*%]?$')
  if param:sub(1, 1) == '\\' or param:sub(1, 2) == '[\\' then
    if name then
      movel_optionals[name:lower()] = true
    end
  else
    movel_optionals = {} -- a required one: only the optional ones after it
  end
end

-- ------------------------------------------------------------ the checks
check('filetype detection: extensions in any case, content for .mod/.sys/.prg', function()
  local cases = {
    { 'a/Main.mod', { 'MODULE Main', 'ENDMODULE' }, 'rapid' },
    { 'a/MAIN.MOD', { 'MODULE Main', 'ENDMODULE' }, 'rapid' },
    { 'a/Main.Mod', { '', '  module Main(SYSMODULE)' }, 'rapid' },
    { 'a/user.sys', { '%%%', '  VERSION:1', '%%%' }, 'rapid' },
    { 'a/user.SYS', { 'MODULE user(SYSMODULE)' }, 'rapid' },
    { 'a/x.prg', { 'MODULE x' }, 'rapid' },
    { 'a/Main.modx', { 'whatever' }, 'rapid' },
    { 'a/BASE.SYSX', { 'whatever' }, 'rapid' },
    { 'a/go.mod', { 'module example.com/x', '', 'go 1.22' }, 'gomod' },
  }
  -- functions that look at the content need a buffer (with only `contents`
  -- Neovim hands them none)
  local function detect(name, content)
    local b = vim.api.nvim_create_buf(false, true)
    vim.api.nvim_buf_set_lines(b, 0, -1, false, content)
    local ft = vim.filetype.match({ buf = b, filename = name })
    vim.api.nvim_buf_delete(b, { force = true })
    return ft
  end
  for _, c in ipairs(cases) do
    local ft = detect(c[1], c[2])
    expect(ft == c[3], '%s: filetype %s, expected %s', c[1], tostring(ft), c[3])
  end
  -- other languages' .sys and .mod files are not RAPID
  for _, c in ipairs({
    { 'c/config.sys', { 'DEVICE=HIMEM.SYS', 'FILES=40' } },
    { 'c/CONFIG.SYS', { 'DEVICE=HIMEM.SYS', 'FILES=40' } },
    { 'm/Lists.mod', { 'MODULE Lists;', 'IMPORT InOut;' } },
  }) do
    local ft = detect(c[1], c[2])
    expect(ft ~= 'rapid' and ft ~= nil, '%s detected as %s', c[1], tostring(ft))
  end
end)

check('the nvim-lspconfig configuration registers (with a stand-in lspconfig.configs)', function()
  -- nvim-lspconfig is not installed here: its configs table is a plain table
  package.loaded['lspconfig.configs'] = {}
  require('rapid.lspconfig').register()
  local entry = package.loaded['lspconfig.configs'].rapid
  package.loaded['lspconfig.configs'] = nil
  expect(entry and entry.default_config, 'no rapid entry')
  local d = entry.default_config
  expect(vim.deep_equal(d.cmd, { 'rapid', 'lsp' }) and vim.deep_equal(d.filetypes, { 'rapid' }),
    'default_config %s', vim.inspect(d))
  local root = d.root_dir(ws .. '/MainModule.mod')
  expect(root == ws, 'root_dir %s, expected the folder with EIO.cfg %s', tostring(root), ws)
end)

-- headless Neovim writes notifications to stderr without a newline
vim.notify = function(msg)
  say('notify: ' .. msg)
end
vim.cmd('RapidBuildParser')

check('the parser builds for Neovim 0.10 too (ABI 14, regenerated with the tree-sitter CLI)', function()
  expect(vim.fn.executable('tree-sitter') == 1, 'the tree-sitter CLI is not on PATH')
  local out = vim.fn.tempname() .. '/rapid14.so'
  require('rapid').build_parser(nil, { abi = 14, out = out })
  vim.treesitter.language.add('rapid14', { path = out, symbol_name = 'rapid' })
  expect(vim.treesitter.language.inspect('rapid14').abi_version == 14, 'ABI %s',
    tostring(vim.treesitter.language.inspect('rapid14').abi_version))
  local tree = vim.treesitter.get_string_parser('MODULE m\n  PROC main()\n  ENDPROC\nENDMODULE\n', 'rapid14'):parse()[1]
  expect(not tree:root():has_error(), 'the ABI 14 parser fails on a module: %s', tree:root():sexpr())
end)

vim.cmd('edit ' .. vim.fn.fnameescape(main_path))
local buf = vim.api.nvim_get_current_buf()

check('the seeded module opens as RAPID', function()
  expect(vim.bo[buf].filetype == 'rapid', 'filetype is %q', vim.bo[buf].filetype)
  expect(vim.bo[buf].commentstring == '! %s', 'commentstring is %q', vim.bo[buf].commentstring)
end)

check('tree-sitter highlighting starts with the project queries', function()
  expect(require('rapid').has_parser(), 'the rapid parser did not load after :RapidBuildParser')
  expect(vim.treesitter.highlighter.active[buf] ~= nil, 'no active tree-sitter highlighter')
  vim.treesitter.get_parser(buf, 'rapid'):parse(true)
  local function captures_at(needle, offset)
    local row, l = line_of(needle)
    local col = l:find(needle, 1, true) - 1 + (offset or 0)
    local names = {}
    for _, c in ipairs(vim.treesitter.get_captures_at_pos(buf, row, col)) do
      names[c.capture] = true
    end
    return names, row, col
  end
  local expectations = {
    { 'PROC GoHome', 0, 'keyword.function' },
    { 'GoHome()', 0, 'function' },
    { 'WaitTime 0.2', 0, 'function.call' },
    { 'CONST num nRows', 6, 'type.builtin' }, -- the #match? rewritten for Vim regexes
    { 'CONST num nRows', 10, 'constant' },
    { 'PlaceBox(num layer', 13, 'variable.parameter' },
    { 'tGripper\\WObj', 9, 'variable.parameter' },
    { '"Pallet complete: "', 0, 'string' },
    { '! Picks boxes', 0, 'comment' },
  }
  for _, e in ipairs(expectations) do
    local names, row, col = captures_at(e[1], e[2])
    expect(names[e[3]], '@%s expected at %d:%d (%s), found {%s}', e[3], row + 1, col + 1, e[1],
      table.concat(vim.tbl_keys(names), ', '))
  end
  -- and the types of user code are not built-in
  local names = captures_at('VAR intnum irStop', 4)
  expect(names['type.builtin'], 'intnum should be @type.builtin')
end)

check('folds query is valid for this Neovim', function()
  local q = vim.treesitter.query.get('rapid', 'folds')
  expect(q ~= nil, 'no folds query')
  local level = vim.treesitter.foldexpr(line_of('PROC PickBox') + 2)
  expect(level ~= '0', 'no fold level inside PickBox: %s', level)
end)

local client
check('the language server attaches', function()
  local ok = vim.wait(TIMEOUT, function()
    local clients = vim.lsp.get_clients({ bufnr = buf, name = 'rapid' })
    client = clients[1]
    return client ~= nil and client.initialized
  end, 50)
  expect(ok, 'no rapid client attached to the buffer within %d ms', TIMEOUT)
end)

local function request(method, params, bufnr)
  expect(client ~= nil, 'no client')
  local results, err = vim.lsp.buf_request_sync(bufnr or buf, method, params, TIMEOUT)
  expect(results ~= nil, '%s: %s', method, tostring(err))
  for _, r in pairs(results) do
    expect(r.error == nil, '%s: %s', method, vim.inspect(r.error))
    return r.result
  end
end

--- Waits for a diagnostic of buffer `b` that `pred` accepts; returns it.
local function wait_diagnostic(b, pred, what)
  local found
  local ok = vim.wait(TIMEOUT, function()
    for _, d in ipairs(vim.diagnostic.get(b)) do
      if pred(d) then
        found = d
        return true
      end
    end
    return false
  end, 50)
  expect(ok, 'no diagnostic %s for %s; got %s', what, vim.api.nvim_buf_get_name(b), vim.inspect(vim.diagnostic.get(b)))
  return found
end

--- Writes `files` (path relative to `dir`, lines) below `dir`.
local function write_tree(dir, files)
  for name, content in pairs(files) do
    local path = dir .. '/' .. name
    vim.fn.mkdir(vim.fs.dirname(path), 'p')
    vim.fn.writefile(content, path)
  end
end

--- Closes a buffer opened by a check, and the rapid client it started
--- (unless the seeded module's client).
local function close_buffer(b)
  vim.cmd('buffer ' .. buf)
  for _, c in ipairs(vim.lsp.get_clients({ bufnr = b, name = 'rapid' })) do
    if not vim.lsp.buf_is_attached(buf, c.id) then
      c:stop(true)
    end
  end
  vim.api.nvim_buf_delete(b, { force = true })
end

--- The rapid clients attached to buffer `b` (waiting for one).
local function client_of(b)
  local c
  vim.wait(TIMEOUT, function()
    c = vim.lsp.get_clients({ bufnr = b, name = 'rapid' })[1]
    return c ~= nil and c.initialized
  end, 50)
  expect(c ~= nil, 'no rapid client for %s', vim.api.nvim_buf_get_name(b))
  return c
end

--- (code, 0-based line) of what `rapid check --format json ARGS` says of the file named `name`.
local function check_findings(args, name)
  local cmd = { rapid_bin, 'check', '--format', 'json' }
  vim.list_extend(cmd, args)
  local out = {}
  for _, d in ipairs(vim.json.decode((run(cmd)))) do
    if vim.fs.basename(d.file) == name then
      table.insert(out, d.code .. '@' .. (d.line - 1))
    end
  end
  table.sort(out)
  return out
end

--- The same of Neovim's diagnostics of buffer `b`, once they equal `want`.
local function wait_findings(b, want)
  local got
  local ok = vim.wait(TIMEOUT, function()
    got = {}
    for _, d in ipairs(vim.diagnostic.get(b)) do
      table.insert(got, d.code .. '@' .. d.lnum)
    end
    table.sort(got)
    return vim.deep_equal(got, want)
  end, 50)
  expect(ok, 'diagnostics %s, rapid check says %s', vim.inspect(got), vim.inspect(want))
end

local function position(needle, offset)
  local row, l = line_of(needle)
  return {
    textDocument = { uri = vim.uri_from_bufnr(buf) },
    position = { line = row, character = l:find(needle, 1, true) - 1 + (offset or 0) },
  }
end

check(('a diagnostic appears for the seeded error (%s)'):format(expected[1] and expected[1].code or '?'), function()
  expect(#expected > 0, 'rapid check found no error in the seeded file')
  local want = expected[1]
  local found = wait_diagnostic(buf, function(d)
    return d.code == want.code
  end, want.code)
  expect(found.lnum == want.line - 1 and found.col == want.column - 1,
    'at %d:%d, rapid check says %d:%d', found.lnum + 1, found.col + 1, want.line, want.column)
  expect(found.severity == vim.diagnostic.severity.ERROR, 'severity %s', tostring(found.severity))
  expect(found.message:find(want.message, 1, true), 'message %q, rapid check says %q', found.message, want.message)
end)

check('hover over a built-in call shows its signature', function()
  local result = request('textDocument/hover', position('WaitTime 0.2', 3))
  expect(result and result.contents, 'no hover')
  local text = markup_text(result.contents)
  expect(text:find(wait_time_signature, 1, true), 'hover %q lacks %q', text, wait_time_signature)
end)

--- Expects the hover at `needle` (+ `offset`) to show the value 24.
local function hover_shows_24(needle, offset)
  local result = request('textDocument/hover', position(needle, offset))
  expect(result and result.contents, 'no hover')
  local text = markup_text(result.contents)
  expect(text:find('%f[%d]24%f[%D]'), 'hover %q does not show the value 24', text)
end

check('hover over a constant expression shows its value', function()
  hover_shows_24('\\Num:=nSlots', 8)
end)

check('definition: a routine in the same module, a tool in the other module', function()
  local function target(needle, offset)
    local result = request('textDocument/definition', position(needle, offset))
    expect(result ~= nil, 'no definition for %s', needle)
    local loc = result.uri and result or result[1]
    expect(loc ~= nil, 'empty definition for %s', needle)
    local uri = loc.uri or loc.targetUri
    local range = loc.range or loc.targetSelectionRange
    return vim.uri_to_fname(uri), range.start.line
  end
  local file, line = target('PickBox;', 2)
  expect(vim.fs.basename(file) == 'MainModule.mod', 'PickBox defined in %s', file)
  expect(line == line_of('PROC PickBox'), 'PickBox defined at line %d', line + 1)
  file, line = target('fine, tGripper;', 8)
  expect(vim.fs.basename(file) == 'Cell.sys', 'tGripper defined in %s', file)
  local cell = vim.fn.readfile(ws .. '/Cell.sys')
  expect(cell[line + 1] and cell[line + 1]:find('tGripper', 1, true), 'line %d of Cell.sys: %s', line + 1,
    tostring(cell[line + 1]))
end)

--- Inserts `code` (indented as the statements of PickBox) as a new line
--- after `WaitTime 0.2;`, asks for completion at its end (with `context`),
--- removes it again; returns the items sorted by sortText and the position.
local function completion_on_new_line(code, context)
  local row, l = line_of('WaitTime 0.2;')
  local text = l:match('^%s*') .. code
  vim.api.nvim_buf_set_lines(buf, row + 1, row + 1, false, { text })
  local at = { textDocument = { uri = vim.uri_from_bufnr(buf) }, position = { line = row + 1, character = #text } }
  local ok, result = pcall(request, 'textDocument/completion', vim.tbl_extend('force', at, { context = context }))
  local help = ok and code:sub(-1) == '\\' and request('textDocument/signatureHelp', at) or nil
  vim.api.nvim_buf_set_lines(buf, row + 1, row + 2, false, {})
  expect(ok, '%s', tostring(result))
  local items = result and (result.items or result) or {}
  table.sort(items, function(a, b)
    return (a.sortText or a.label) < (b.sortText or b.label)
  end)
  return items, help
end

check('completion after tool\\ lists only the optional arguments that may follow', function()
  local items = completion_on_new_line('MoveL pPickAbove, v300, fine, tGripper\\',
    { triggerKind = 2, triggerCharacter = '\\' })
  local labels, known = {}, 0
  for _, item in ipairs(items) do
    local label = item.label:gsub('^\\', ''):match('^[%w_]+') or item.label
    table.insert(labels, label)
    if movel_optionals[label:lower()] then
      known = known + 1
    end
  end
  local total = vim.tbl_count(movel_optionals)
  expect(total > 0 and known == total and #labels == total,
    'completion lists %s; the optional arguments after Tool in `rapid builtins MoveL` are %s',
    table.concat(labels, ' '), table.concat(vim.tbl_keys(movel_optionals), ' '))
end)

check('a blank after MoveL opens its first argument: the robtargets, the most used first', function()
  local items = completion_on_new_line('MoveL ', { triggerKind = 2, triggerCharacter = ' ' })
  local first = items[1] and items[1].label
  -- the robtarget the module uses most
  local counts = {}
  for _, l in ipairs(lines) do
    for name in l:gmatch('[%a_][%w_]*') do
      counts[name] = (counts[name] or 0) + 1
    end
  end
  -- in scope where the line goes (after `WaitTime 0.2;`): the module's
  -- and that routine's own
  local here = line_of('WaitTime 0.2;') + 1
  local function opens(l)
    local u = l:upper()
    return u:match('^%s*PROC%s') or u:match('^%s*FUNC%s') or u:match('^%s*TRAP%s')
      or u:match('^%s*LOCAL%s+PROC%s') or u:match('^%s*LOCAL%s+FUNC%s') or u:match('^%s*LOCAL%s+TRAP%s')
  end
  local function closes(l)
    local u = l:upper()
    return u:match('^%s*ENDPROC') or u:match('^%s*ENDFUNC') or u:match('^%s*ENDTRAP')
  end
  local robtargets, start = {}, nil
  for i, l in ipairs(lines) do
    if opens(l) then
      start = i
    end
    local name = l:match('^%s*[%a]+%s+robtarget%s+([%a_][%w_]*)')
    local last = i
    while start and lines[last] and not closes(lines[last]) do
      last = last + 1
    end
    if name and (start == nil or (start <= here and here <= last)) then
      table.insert(robtargets, name)
    end
    if closes(l) then
      start = nil
    end
  end
  table.sort(robtargets, function(a, b)
    return counts[a] > counts[b] or (counts[a] == counts[b] and a:lower() < b:lower())
  end)
  expect(#robtargets > 0 and first == robtargets[1], 'first item %s, expected %s (of %s)', tostring(first),
    tostring(robtargets[1]), table.concat(robtargets, ' '))
  for _, item in ipairs(items) do
    expect(item.label ~= 'nPlaced', 'a num offered for a robtarget')
  end
  local none = completion_on_new_line('IF nPlaced ', { triggerKind = 2, triggerCharacter = ' ' })
  expect(#none == 0, 'a blank after a condition offered %d items', #none)
end)

check('indentation is the formatter\'s: the file\'s own (4 spaces here), or [format] indent-width of rapid.toml', function()
  expect(vim.bo[buf].shiftwidth == 4 and vim.bo[buf].softtabstop == 4 and vim.bo[buf].expandtab,
    'shiftwidth %d, softtabstop %d, expandtab %s (Neovim\'s indent/rapid.vim sets 2)', vim.bo[buf].shiftwidth,
    vim.bo[buf].softtabstop, tostring(vim.bo[buf].expandtab))
  -- = reindents a statement of a routine as rapid fmt writes it (two levels)
  local row, l = line_of('WaitTime 0.2;')
  vim.api.nvim_buf_set_lines(buf, row, row + 1, false, { 'WaitTime 0.2;' })
  vim.api.nvim_win_set_cursor(0, { row + 1, 0 })
  vim.cmd('normal! ==')
  local got = vim.api.nvim_buf_get_lines(buf, row, row + 1, false)[1]
  vim.api.nvim_buf_set_lines(buf, row, row + 1, false, { l })
  expect(got == l, 'reindented to %q, rapid fmt writes %q', got, l)
  local dir = vim.fn.tempname()
  write_tree(dir, { ['rapid.toml'] = { '[lint]', 'ignore = []', '', '[format]', 'indent-width = 3' },
    ['sub/A.mod'] = { 'MODULE A', 'ENDMODULE' } })
  vim.cmd('edit ' .. vim.fn.fnameescape(dir .. '/sub/A.mod'))
  local other = vim.api.nvim_get_current_buf()
  local sw = vim.bo[other].shiftwidth
  client_of(other) -- closed before its server starts, the start fails on a deleted buffer
  close_buffer(other)
  expect(sw == 3, 'shiftwidth %d below a rapid.toml with indent-width = 3', sw)
  -- without a configured width, a file indented by 2 keeps 2 (as rapid fmt does)
  local plain = vim.fn.tempname()
  write_tree(plain, { ['B.mod'] = { 'MODULE B', '  PROC p()', '    TPWrite "x";', '  ENDPROC', 'ENDMODULE' } })
  vim.cmd('edit ' .. vim.fn.fnameescape(plain .. '/B.mod'))
  local two = vim.api.nvim_get_current_buf()
  local sw2, et = vim.bo[two].shiftwidth, vim.bo[two].expandtab
  client_of(two)
  close_buffer(two)
  expect(sw2 == 2 and et, 'shiftwidth %d, expandtab %s for a file indented by 2', sw2, tostring(et))
end)

check('indentation of mixed files: the server\'s answer, the majority\'s, as rapid fmt writes it', function()
  local dir = vim.fn.tempname()
  local spaces = { 'MODULE S', '    PROC p()', '        x := 1;', '\ty := 2;', '        IF x > 0 THEN',
    '            z := 3;', '        ENDIF', '    ENDPROC', 'ENDMODULE' }
  local tabs = { 'MODULE T', '\tPROC p()', '\t\tx := 1;', '      y := 2;', '\t\tIF x > 0 THEN',
    '\t\t\tz := 3;', '\t\tENDIF', '\tENDPROC', 'ENDMODULE' }
  write_tree(dir, { ['S.mod'] = spaces, ['T.mod'] = tabs })
  for _, case in ipairs({ { 'S.mod', false }, { 'T.mod', true } }) do
    local path = dir .. '/' .. case[1]
    vim.cmd('edit ' .. vim.fn.fnameescape(path))
    local b = vim.api.nvim_get_current_buf()
    client_of(b)
    local ok = vim.wait(TIMEOUT, function()
      return vim.b[b].rapid_indentation ~= nil
    end, 50)
    local answer = vim.b[b].rapid_indentation
    local et, sw = vim.bo[b].expandtab, vim.bo[b].shiftwidth
    -- = on the odd line writes it as rapid fmt does
    vim.api.nvim_win_set_cursor(0, { 4, 0 })
    vim.cmd('normal! ==')
    local got = vim.api.nvim_buf_get_lines(b, 3, 4, false)[1]
    local fmt_out = vim.system({ rapid_bin, 'fmt', '-' }, { stdin = table.concat(vim.fn.readfile(path), '\n') .. '\n', text = true }):wait()
    local formatted = vim.split(fmt_out.stdout or "", "\n")
    close_buffer(b)
    expect(ok, '%s: no answer to rapid/indentation', case[1])
    expect(answer.tabs == case[2] and answer.width == 4, '%s: the server says %s', case[1], vim.inspect(answer))
    expect(et == not case[2] and sw == 4, '%s: expandtab %s, shiftwidth %d', case[1], tostring(et), sw)
    expect(got == formatted[4], '%s: = wrote %q, rapid fmt writes %q', case[1], got, tostring(formatted[4]))
  end
end)

check('a file that is not open has its diagnostics too (Cell.sys, as rapid check says)', function()
  expect(#cell_expected > 0, 'rapid check found nothing in Cell.sys')
  local cell = vim.fn.bufadd(ws .. '/Cell.sys')
  local want = cell_expected[1]
  local d = wait_diagnostic(cell, function(d)
    return d.code == want.code
  end, want.code)
  expect(d.lnum == want.line - 1 and d.col == want.column - 1, 'at %d:%d, rapid check says %d:%d', d.lnum + 1,
    d.col + 1, want.line, want.column)
  expect(not vim.api.nvim_buf_is_loaded(cell), 'Cell.sys was loaded')
end)

check('an edit in one module updates the diagnostics of the other open module of the task', function()
  vim.cmd('edit ' .. vim.fn.fnameescape(ws .. '/Cell.sys'))
  local cell = vim.api.nvim_get_current_buf()
  client_of(cell)
  local cell_lines = vim.api.nvim_buf_get_lines(cell, 0, -1, false)
  local row
  for i, l in ipairs(cell_lines) do
    if l:find('PERS tooldata tGripper', 1, true) then
      row = i - 1
    end
  end
  expect(row ~= nil, 'no tGripper in Cell.sys')
  local before = cell_lines[row + 1]
  -- rename the tool in Cell.sys (unsaved): MainModule, not edited, now
  -- uses a name that does not exist
  vim.api.nvim_buf_set_lines(cell, row, row + 1, false, { (before:gsub('tGripper', 'tGripperRenamed')) })
  wait_diagnostic(buf, function(d)
    return d.message:find('tGripper', 1, true) ~= nil
  end, 'about tGripper in MainModule.mod')
  vim.api.nvim_buf_set_lines(cell, row, row + 1, false, { before })
  local ok = vim.wait(TIMEOUT, function()
    for _, d in ipairs(vim.diagnostic.get(buf)) do
      if d.message:find('tGripper', 1, true) then
        return false
      end
    end
    return true
  end, 50)
  expect(ok, 'MainModule.mod keeps %s', vim.inspect(vim.diagnostic.get(buf)))
  vim.cmd('buffer ' .. buf)
end)

check('completion after \\ offers first what can come next; signature help marks it, with types', function()
  local items, help = completion_on_new_line('MoveL pPickAbove, v300, fine, tGripper\\',
    { triggerKind = 2, triggerCharacter = '\\' })
  expect(items[1] and items[1].label == 'WObj', 'first item %s', items[1] and items[1].label or 'none')
  local sig = help and help.signatures and help.signatures[1]
  expect(sig, 'no signature help')
  local active = help.activeParameter or sig.activeParameter
  local range = sig.parameters[active + 1].label
  local label = type(range) == 'string' and range or sig.label:sub(range[1] + 1, range[2])
  expect(label == '[\\PERS wobjdata WObj]', 'active parameter %q in %s', label, sig.label)
  expect(sig.label:find('robtarget ToPoint', 1, true), 'no types in %s', sig.label)
end)

check('MoveL ranks first at the start of a statement', function()
  local items = completion_on_new_line('', { triggerKind = 1 })
  expect(items[1] and items[1].label == 'MoveL', 'first item %s', items[1] and items[1].label or 'none')
end)

check('hover on a constant\'s declaration shows its value, as on its use', function()
  hover_shows_24('CONST num nSlots', 12)
end)

check('parameter names are hinted before literals, not before names', function()
  local result = request('textDocument/inlayHint', { textDocument = { uri = vim.uri_from_bufnr(buf) },
    range = { start = { line = 0, character = 0 }, ['end'] = { line = #lines, character = 0 } } }) or {}
  local hints = {}
  for _, h in ipairs(result) do
    local label = type(h.label) == 'string' and h.label or h.label[1].value
    local text = vim.api.nvim_buf_get_lines(buf, h.position.line, h.position.line + 1, false)[1] or ''
    hints[#hints + 1] = label .. ' ' .. text:sub(h.position.character + 1):match('^[^,;)]*')
  end
  local has = function(s)
    return vim.tbl_contains(hints, s)
  end
  expect(has('Value: 1') and has('ZOffset: 100'), 'hints %s', vim.inspect(hints))
  for _, h in ipairs(hints) do
    expect(not h:find('ToPoint: pPickAbove', 1, true) and not h:find('Tool:', 1, true), 'hint %s', h)
  end
end)

check('a controller backup is a project root (BACKINFO, SYSPAR, RAPID): its task and configuration load', function()
  local backup = vim.fn.tempname() .. '/BACKUP'
  write_tree(backup, {
    ['BACKINFO/backinfo.txt'] = { 'backup' },
    ['SYSPAR/EIO.cfg'] = { 'EIO:CFG_1.0:6:1::', '#', 'EIO_SIGNAL:', '', '      -Name "diGo" -SignalType "DI" -Device "d652"' },
    ['RAPID/TASK1/PROGMOD/Main.mod'] = { 'MODULE Main', '    PROC main()', '        VAR num nUnused;',
      '        LibHelper;', '        WaitDI diGo, 1;', '    ENDPROC', 'ENDMODULE' },
    ['RAPID/TASK1/SYSMOD/Lib.sys'] = { 'MODULE Lib(SYSMODULE)', '    PROC LibHelper()', '    ENDPROC', 'ENDMODULE' },
  })
  local main = backup .. '/RAPID/TASK1/PROGMOD/Main.mod'
  expect(require('rapid').find_root(main) == backup, 'root %s', tostring(require('rapid').find_root(main)))
  local want = check_findings({ backup }, 'Main.mod')
  expect(vim.deep_equal(want, { 'W201@2' }), 'rapid check says %s', vim.inspect(want))
  vim.cmd('edit ' .. vim.fn.fnameescape(main))
  local b = vim.api.nvim_get_current_buf()
  local c = client_of(b)
  if c.root_dir ~= backup then
    close_buffer(b)
    error(('the client\'s root is %s'):format(tostring(c.root_dir)))
  end
  wait_findings(b, want)
  local found = request('textDocument/definition',
    { textDocument = { uri = vim.uri_from_bufnr(b) }, position = { line = 3, character = 10 } }, b)
  local loc = found and (found.uri and found or found[1])
  close_buffer(b)
  expect(loc and vim.uri_to_fname(loc.uri or loc.targetUri):find('SYSMOD/Lib.sys', 1, true), 'definition %s',
    vim.inspect(found))
end)

check('a file outside any project gets its task from its folder', function()
  local dir = vim.fn.tempname() .. '/loose'
  write_tree(dir, {
    ['A.mod'] = { 'MODULE A', '    PROC main()', '        VAR num nUnused;', '        BHelper;', '    ENDPROC', 'ENDMODULE' },
    ['B.mod'] = { 'MODULE B', '    PROC BHelper()', '    ENDPROC', 'ENDMODULE' },
  })
  expect(require('rapid').find_root(dir .. '/A.mod') == nil, 'a root above %s: %s', dir,
    tostring(require('rapid').find_root(dir .. '/A.mod')))
  local want = check_findings({ dir .. '/A.mod' }, 'A.mod')
  expect(vim.deep_equal(want, { 'W201@2' }), 'rapid check says %s', vim.inspect(want))
  vim.cmd('edit ' .. vim.fn.fnameescape(dir .. '/A.mod'))
  local b = vim.api.nvim_get_current_buf()
  local c = client_of(b)
  local root = c.root_dir
  local ok, err = pcall(wait_findings, b, want)
  close_buffer(b)
  expect(root == nil, 'the client\'s root is %s', tostring(root))
  expect(ok, '%s', tostring(err))
end)

check(':RapidRestart starts a new server that publishes the diagnostics again', function()
  local old = client.id
  vim.cmd('RapidRestart')
  local new
  local ok = vim.wait(TIMEOUT, function()
    new = vim.lsp.get_clients({ bufnr = buf, name = 'rapid' })[1]
    return new ~= nil and new.id ~= old and new.initialized
  end, 50)
  expect(ok, 'no new rapid client after :RapidRestart')
  expect(#vim.lsp.get_clients({ name = 'rapid' }) == 1, '%d rapid clients', #vim.lsp.get_clients({ name = 'rapid' }))
  ok = vim.wait(TIMEOUT, function()
    for _, d in ipairs(vim.diagnostic.get(buf)) do
      if d.code == expected[1].code then
        return true
      end
    end
    return false
  end, 50)
  expect(ok, 'no %s diagnostic from the new server', expected[1].code)
end)

check(':checkhealth rapid: binary and version, parser, queries, server attached, root', function()
  vim.cmd('buffer ' .. buf)
  client_of(buf)
  vim.cmd('checkhealth rapid')
  local report = table.concat(vim.api.nvim_buf_get_lines(0, 0, -1, false), '\n')
  vim.cmd('bwipeout!')
  vim.cmd('buffer ' .. buf)
  if log_path then
    vim.fn.writefile(vim.split(report, '\n'), vim.fs.dirname(log_path) .. '/neovim-checkhealth.txt')
  end
  local version = vim.trim(run({ rapid_bin, '--version' }))
  for _, want in ipairs({ version, 'the parser loads', 'the queries are current and load', 'the server is attached',
    'project root: ' .. ws, 'indentation from the server' }) do
    expect(report:find(want, 1, true), 'no %q in the report:\n%s', want, report)
  end
  expect(not report:find('ERROR', 1, true), 'an error in the report:\n%s', report)
end)

check('a missing server binary: a message says what is missing and how to install it; :checkhealth says it too', function()
  local rapid = require('rapid')
  local saved = vim.deepcopy(rapid.config)
  local messages = {}
  local notify = vim.notify
  vim.notify = function(msg, level)
    table.insert(messages, { msg = msg, level = level })
  end
  local ok, err = pcall(function()
    rapid.setup(vim.tbl_extend('force', saved, { cmd = { '/no/such/dir/rapid', 'lsp' } }))
    local dir = vim.fn.tempname()
    write_tree(dir, { ['M.mod'] = { 'MODULE M', 'ENDMODULE' } })
    vim.cmd('edit ' .. vim.fn.fnameescape(dir .. '/M.mod'))
    local b = vim.api.nvim_get_current_buf()
    vim.wait(1000, function()
      return #messages > 0
    end, 50)
    vim.cmd('checkhealth rapid')
    local report = table.concat(vim.api.nvim_buf_get_lines(0, 0, -1, false), '\n')
    vim.cmd('bwipeout!')
    close_buffer(b)
    local text = messages[1] and messages[1].msg or ''
    expect(text:find('/no/such/dir/rapid', 1, true) and text:find('cargo install --path lsp', 1, true),
      'message: %q', text)
    expect(messages[1].level == vim.log.levels.WARN, 'level %s', tostring(messages[1].level))
    expect(report:find('cannot be run', 1, true) and report:find('cargo install --path lsp', 1, true),
      'report:\n%s', report)
  end)
  vim.notify = notify
  rapid.setup(saved)
  expect(ok, '%s', tostring(err))
end)

-- :RapidDiff, in a file of its own
dofile(vim.fs.dirname(debug.getinfo(1, 'S').source:sub(2)) .. '/diff.lua')({
  check = check,
  expect = expect,
  run = run,
  ws = ws,
  rapid_bin = rapid_bin,
})

-- The robot's path following the debugger (nvim-dap), in a file of its own
dofile(vim.fs.dirname(debug.getinfo(1, 'S').source:sub(2)) .. '/dap.lua')({
  check = check,
  expect = expect,
  timeout = TIMEOUT,
})

finish()
