-- ABB RAPID for Neovim 0.10 and later: filetype detection, the rapid
-- language server, and the tree-sitter parser with the project's queries.
--
--   require('rapid').setup({
--     cmd = { 'rapid', 'lsp' },   -- the language server command
--     lsp = true,                 -- start it for RAPID buffers
--     highlight = true,           -- vim.treesitter.start() when the parser is built
--     folds = false,              -- fold with the tree-sitter folds query
--     indent_width = nil,         -- spaces per level; nil: [format] indent-width, else the file's own
--                                 -- of the rapid.toml above the file, else 4
--   })
local M = {}

local defaults = {
  cmd = { 'rapid', 'lsp' },
  lsp = true,
  highlight = true,
  folds = false,
  -- A project's root holds one of these; a controller backup has BACKINFO,
  -- SYSPAR and RAPID (and no .git). A folder with a .pgf program is one too.
  root_markers = { 'rapid.toml', 'EIO.cfg', 'eio.cfg', 'BACKINFO', 'SYSPAR', 'RAPID', '.git' },
  indent_width = nil,
  grammar_dir = nil, -- default: tree-sitter-rapid/ of the repository holding this plugin
}

M.config = vim.deepcopy(defaults)

local function plugin_root()
  local source = debug.getinfo(1, 'S').source:sub(2)
  return vim.fs.dirname(vim.fs.dirname(vim.fs.dirname(vim.fs.normalize(source))))
end

--- Directory of the plugin (editors/neovim).
M.root = plugin_root()

local lsp_group = vim.api.nvim_create_augroup('rapid_lsp', { clear = true })
local indent_group = vim.api.nvim_create_augroup('rapid_indent', { clear = true })

--- Is a folder entry named `name` a root marker (one of `root_markers`, or
--- a `.pgf` program file in any case)?
local function is_root_marker(name)
  for _, m in ipairs(M.config.root_markers) do
    if name == m then
      return true
    end
  end
  return name:lower():match('%.pgf$') ~= nil
end

--- The project root of a file (or buffer): the nearest folder above it that
--- holds a root marker; nil when none does (the server then finds the
--- file's task from its place).
---@param source string|integer a path or a buffer number
---@return string|nil
function M.find_root(source)
  return vim.fs.root(source, function(name)
    return is_root_marker(name)
  end)
end

--- Spaces per indentation level when configured: `indent_width` of the
--- setup, else `[format] indent-width` of the nearest rapid.toml above
--- `path`; nil when neither sets it (then `rapid fmt` keeps each file's own
--- indentation, see `own_indentation`).
---@param path string
---@return integer?
function M.indent_width(path)
  if M.config.indent_width then
    return M.config.indent_width
  end
  local found = vim.fs.find('rapid.toml', { upward = true, path = vim.fs.dirname(path), type = 'file' })[1]
  local width
  if found then
    local section
    for _, line in ipairs(vim.fn.readfile(found)) do
      local name = line:match('^%s*%[%s*([%w%.%-_]+)%s*%]')
      if name then
        section = name
      elseif section == 'format' then
        local n = line:match('^%s*indent%-width%s*=%s*(%d+)')
        if n then
          width = tonumber(n)
        end
      end
    end
  end
  if width and width >= 1 and width <= 16 then
    return width
  end
  return nil
end

--- A buffer's own indentation until the language server says what the
--- formatter finds (`rapid/indentation`, see `apply_indentation`): the
--- most common step by which a line is indented deeper than the line
--- before it (4 when the buffer has none), with tabs if most of the lines
--- indented by 4 columns or more start with one (the formatter's rule: a
--- file of spaces with one line typed with a tab stays a file of spaces).
--- Looks at the first 2,000 lines.
---@param bufnr integer
---@return integer width, boolean tabs
function M.own_indentation(bufnr)
  local lines = vim.api.nvim_buf_get_lines(bufnr, 0, 2000, false)
  local steps, previous = {}, 0
  local tab_led, space_led = 0, 0
  for _, line in ipairs(lines) do
    if line:find('%S') then
      local lead = line:match('^[ \t]*')
      local n = 0
      for c in lead:gmatch('.') do
        n = c == '\t' and (math.floor(n / 4) + 1) * 4 or n + 1
      end
      if n >= 4 then
        if lead:sub(1, 1) == '\t' then
          tab_led = tab_led + 1
        else
          space_led = space_led + 1
        end
      end
      if n > previous then
        steps[n - previous] = (steps[n - previous] or 0) + 1
      end
      previous = n
    end
  end
  local best, count = 4, 0
  for step, c in pairs(steps) do
    if step <= 16 and (c > count or (c == count and step < best)) then
      best, count = step, c
    end
  end
  return best, tab_led > space_led
end

--- Sets the buffer's indentation options: `width` columns per level,
--- written with tabs or spaces.
local function set_options(bufnr, width, tabs)
  vim.bo[bufnr].shiftwidth = width
  vim.bo[bufnr].softtabstop = tabs and 0 or width
  vim.bo[bufnr].tabstop = tabs and 4 or vim.bo[bufnr].tabstop
  vim.bo[bufnr].expandtab = not tabs
end

--- Indentation as the formatter writes it: the configured width, else the
--- buffer's own (until the server answers). Runs after Neovim's own
--- indent/rapid.vim (which sets 2).
local function set_indentation(bufnr)
  local name = vim.api.nvim_buf_get_name(bufnr)
  local width = M.indent_width(name ~= '' and name or (vim.uv.cwd() .. '/x.mod'))
  local tabs = false
  if not width then
    width, tabs = M.own_indentation(bufnr)
  end
  set_options(bufnr, width, tabs)
end

--- Asks the language server how the formatter indents the buffer
--- (`rapid/indentation`: the width of `[format] indent-width`, or the
--- file's own unit and tabs or spaces as most of its lines have them) and
--- sets the buffer's options from the answer, so that `=`, `>>` and new
--- lines indent as `rapid fmt` does. The `indent_width` of the setup wins.
---@param client vim.lsp.Client
---@param bufnr integer
function M.apply_indentation(client, bufnr)
  if M.config.indent_width then
    return
  end
  local params = { textDocument = { uri = vim.uri_from_bufnr(bufnr) } }
  local handler = function(err, result)
    if err or type(result) ~= 'table' or type(result.width) ~= 'number' then
      return
    end
    if vim.api.nvim_buf_is_valid(bufnr) then
      set_options(bufnr, result.width, result.tabs == true)
      vim.b[bufnr].rapid_indentation = result
    end
  end
  if vim.fn.has('nvim-0.11') == 1 then
    client:request('rapid/indentation', params, handler, bufnr)
  else
    client.request('rapid/indentation', params, handler, bufnr)
  end
end

--- The language server's executable, as the `cmd` of the setup names it,
--- if it can be run.
---@return string|nil
function M.server_binary()
  local cmd = M.config.cmd
  local name = type(cmd) == 'table' and cmd[1] or nil
  if type(name) ~= 'string' or vim.fn.executable(name) == 0 then
    return nil
  end
  return vim.fn.exepath(name)
end

--- What to say when the language server's binary cannot be run.
function M.missing_binary_message()
  local cmd = M.config.cmd
  local name = type(cmd) == 'table' and tostring(cmd[1]) or tostring(cmd)
  return table.concat({
    ('rapid: the language server `%s` was not found%s, so RAPID buffers have no diagnostics, hover or completion.'):format(
      name, name:find('/') and '' or ' on PATH'),
    'Install it from a clone of the rapid repository with `cargo install --path lsp` (it puts `rapid` in ~/.cargo/bin),',
    "or give its path: require('rapid').setup({ cmd = { '/path/to/rapid', 'lsp' } }).",
    'Then :RapidRestart. :checkhealth rapid checks the whole setup.',
  }, '\n')
end

local warned_missing = false

--- Says once per session that the server's binary is missing.
local function warn_missing()
  if warned_missing then
    return
  end
  warned_missing = true
  vim.notify(M.missing_binary_message(), vim.log.levels.WARN)
end

local function setup_indent()
  vim.api.nvim_clear_autocmds({ group = indent_group })
  vim.api.nvim_create_autocmd('FileType', {
    group = indent_group,
    pattern = 'rapid',
    callback = function(args)
      set_indentation(args.buf)
    end,
  })
  for _, buf in ipairs(vim.api.nvim_list_bufs()) do
    if vim.api.nvim_buf_is_loaded(buf) and vim.bo[buf].filetype == 'rapid' then
      set_indentation(buf)
    end
  end
end

local function setup_lsp()
  vim.api.nvim_clear_autocmds({ group = lsp_group })
  local has_enable = vim.lsp.config ~= nil and vim.lsp.enable ~= nil
  if not M.config.lsp then
    if has_enable then
      vim.lsp.enable('rapid', false)
    end
    return
  end
  -- the server tells each buffer how the formatter indents it
  vim.api.nvim_create_autocmd('LspAttach', {
    group = lsp_group,
    callback = function(args)
      local client = vim.lsp.get_client_by_id(args.data.client_id)
      if client and client.name == 'rapid' then
        M.apply_indentation(client, args.buf)
      end
    end,
  })
  if not M.server_binary() then
    -- nothing to start: say what is missing when a RAPID buffer opens
    if has_enable then
      vim.lsp.enable('rapid', false)
    end
    vim.api.nvim_create_autocmd('FileType', {
      group = lsp_group,
      pattern = 'rapid',
      callback = warn_missing,
    })
    return
  end
  if has_enable then
    -- Neovim 0.11: lsp/rapid.lua on 'runtimepath' holds the defaults. A
    -- file outside any project starts the server without a root: it finds
    -- the file's task (a backup's RAPID/TASKn, or its folder) itself.
    vim.lsp.config('rapid', {
      cmd = M.config.cmd,
      root_dir = function(bufnr, on_dir)
        on_dir(M.find_root(bufnr))
      end,
    })
    vim.lsp.enable('rapid')
    return
  end
  -- Neovim 0.10
  vim.api.nvim_create_autocmd('FileType', {
    group = lsp_group,
    pattern = 'rapid',
    callback = function(args)
      vim.lsp.start({ name = 'rapid', cmd = M.config.cmd, root_dir = M.find_root(args.buf) }, { bufnr = args.buf })
    end,
  })
end

--- True when the tree-sitter parser for RAPID can be loaded.
function M.has_parser()
  -- 0.10 throws when the parser is missing, 0.11 returns nil: ask inspect()
  if not pcall(vim.treesitter.language.add, 'rapid') then
    return false
  end
  return (pcall(vim.treesitter.language.inspect, 'rapid'))
end

--- Called from ftplugin/rapid.lua for every RAPID buffer.
function M.attach(bufnr)
  if M.config.highlight and M.has_parser() then
    pcall(vim.treesitter.start, bufnr, 'rapid')
    if M.config.folds then
      for _, win in ipairs(vim.fn.win_findbuf(bufnr)) do
        vim.wo[win][0].foldmethod = 'expr'
        vim.wo[win][0].foldexpr = 'v:lua.vim.treesitter.foldexpr()'
      end
    end
  end
end

local function parser_abi(parser_c)
  local f = io.open(parser_c, 'r')
  if not f then
    return nil
  end
  for _ = 1, 40 do
    local line = f:read('*l')
    if not line then
      break
    end
    local abi = line:match('^#define LANGUAGE_VERSION (%d+)')
    if abi then
      f:close()
      return tonumber(abi)
    end
  end
  f:close()
  return nil
end

local function run(cmd, cwd)
  local result = vim.system(cmd, { cwd = cwd, text = true }):wait()
  if result.code ~= 0 then
    error(('%s failed (%d): %s'):format(table.concat(cmd, ' '), result.code, result.stderr or ''), 0)
  end
end

--- Builds parser/rapid.so of this plugin from the repository's tree-sitter-rapid/
--- with a C compiler (`cc`, or $CC). Neovim 0.10 loads parsers of ABI 14 at
--- most: there the grammar is regenerated with `tree-sitter generate --abi 14`
--- (the tree-sitter CLI must be on PATH).
---@param grammar_dir string|nil
---@param opts { abi: integer?, out: string? }|nil  abi: the highest ABI to build for
---  (default: what this Neovim loads); out: the library (default: parser/rapid.so here)
---@return string path of the built parser
function M.build_parser(grammar_dir, opts)
  opts = opts or {}
  grammar_dir = grammar_dir or M.config.grammar_dir or vim.fs.joinpath(M.root, '..', '..', 'tree-sitter-rapid')
  grammar_dir = vim.fs.normalize(vim.fn.fnamemodify(grammar_dir, ':p'))
  local src = vim.fs.joinpath(grammar_dir, 'src')
  if vim.fn.filereadable(vim.fs.joinpath(src, 'parser.c')) == 0 then
    error('no ' .. vim.fs.joinpath(src, 'parser.c') .. ': set grammar_dir to the tree-sitter-rapid folder', 0)
  end
  local abi = parser_abi(vim.fs.joinpath(src, 'parser.c'))
  local max_abi = opts.abi or vim.treesitter.language_version
  if abi and max_abi and abi > max_abi then
    if vim.fn.executable('tree-sitter') == 0 then
      error(('the parser has ABI %d but this Neovim loads ABI %d at most; install the tree-sitter CLI'
        .. ' to regenerate it'):format(abi, max_abi), 0)
    end
    local tmp = vim.fn.tempname()
    vim.fn.mkdir(tmp, 'p')
    run({ 'cp', '-r', vim.fs.joinpath(grammar_dir, 'grammar.js'), tmp })
    run({ 'tree-sitter', 'generate', '--abi', tostring(max_abi) }, tmp)
    run({ 'cp', vim.fs.joinpath(src, 'scanner.c'), vim.fs.joinpath(tmp, 'src') })
    src = vim.fs.joinpath(tmp, 'src')
  end
  local out = opts.out or vim.fs.joinpath(M.root, 'parser', 'rapid.so')
  vim.fn.mkdir(vim.fs.dirname(out), 'p')
  local cc = vim.env.CC or 'cc'
  run({ cc, '-shared', '-fPIC', '-O2', '-I', src, vim.fs.joinpath(src, 'parser.c'),
    vim.fs.joinpath(src, 'scanner.c'), '-o', out }, src)
  return out
end

--- Stops the rapid language server clients and starts them again for the
--- RAPID buffers (looking for the server's binary again).
function M.restart()
  warned_missing = false
  setup_lsp()
  local get = vim.lsp.get_clients or vim.lsp.get_active_clients
  for _, client in ipairs(get({ name = 'rapid' })) do
    client.stop(client, true)
  end
  vim.defer_fn(function()
    for _, buf in ipairs(vim.api.nvim_list_bufs()) do
      if vim.api.nvim_buf_is_loaded(buf) and vim.bo[buf].filetype == 'rapid' then
        vim.api.nvim_exec_autocmds('FileType', { buffer = buf })
      end
    end
  end, 300)
end

--- Applies options (see the defaults at the top of this file).
---@param opts table|nil
function M.setup(opts)
  M.config = vim.tbl_deep_extend('force', vim.deepcopy(defaults), opts or {})
  require('rapid.filetype').register()
  vim.treesitter.language.register('rapid', 'rapid')
  setup_indent()
  setup_lsp()
end

return M
