-- :checkhealth rapid — what the RAPID plugin needs, checked: the language
-- server's binary (found, and its version), the tree-sitter parser (built,
-- and loading), the queries (current with the grammar of this repository,
-- and valid for the parser), the server attached to the current buffer and
-- the project root it was started in.
local M = {}

local health = vim.health

--- The first line of what `cmd` prints, or nil and why not.
local function first_line(cmd)
  local ok, result = pcall(function()
    return vim.system(cmd, { text = true }):wait(5000)
  end)
  if not ok then
    return nil, tostring(result)
  end
  if result.code ~= 0 then
    return nil, vim.trim(result.stderr or '')
  end
  return vim.split(vim.trim(result.stdout or ''), '\n')[1]
end

local function check_binary(rapid)
  health.start('rapid: the language server')
  local cmd = rapid.config.cmd
  local binary = rapid.server_binary()
  if not binary then
    health.error(
      ('`%s` cannot be run'):format(type(cmd) == 'table' and tostring(cmd[1]) or tostring(cmd)),
      vim.split(rapid.missing_binary_message(), '\n')
    )
    return
  end
  local version, why = first_line({ binary, '--version' })
  if version then
    health.ok(('%s: %s'):format(binary, version))
  else
    health.error(('%s --version failed: %s'):format(binary, why or '?'), {
      'Install a current `rapid` (cargo install --path lsp in a clone of the repository).',
    })
  end
  if not rapid.config.lsp then
    health.info('the language server is off (setup({ lsp = false })): start it yourself, e.g. with nvim-lspconfig')
  end
end

local QUERIES = { 'highlights', 'folds', 'indents', 'locals' }

local function check_parser(rapid)
  health.start('rapid: tree-sitter parser and queries')
  if not rapid.has_parser() then
    health.warn('the RAPID parser is not built: no tree-sitter highlighting, folds or indents', {
      'Run :RapidBuildParser (needs a C compiler), or build it with nvim-treesitter (see editors/README.md).',
    })
    return
  end
  local lib = vim.api.nvim_get_runtime_file('parser/rapid.so', false)[1]
  health.ok('the parser loads' .. (lib and (': ' .. lib) or ''))
  -- built from the grammar of this repository, or an older one?
  local grammar = vim.fs.joinpath(rapid.root, '..', '..', 'tree-sitter-rapid', 'src', 'parser.c')
  local built, source = lib and vim.uv.fs_stat(lib), vim.uv.fs_stat(grammar)
  if built and source and built.mtime.sec < source.mtime.sec then
    health.warn('the parser is older than tree-sitter-rapid/src/parser.c', {
      'Run :RapidBuildParser to build it again.',
    })
  end
  for _, name in ipairs(QUERIES) do
    local ok, err = pcall(vim.treesitter.query.get, 'rapid', name)
    if not ok then
      health.error(('the %s query does not load with this parser: %s'):format(name, tostring(err)), {
        'Run :RapidBuildParser: the queries are the grammar\'s, the parser is older.',
      })
    end
  end
  -- the plugin's copies against the grammar's (editors/sync-queries.sh)
  local stale = {}
  for _, name in ipairs(QUERIES) do
    local copy = vim.fs.joinpath(rapid.root, 'queries', 'rapid', name .. '.scm')
    local original = vim.fs.joinpath(rapid.root, '..', '..', 'tree-sitter-rapid', 'queries', name .. '.scm')
    if vim.uv.fs_stat(original) and vim.uv.fs_stat(copy) then
      local want = table.concat(vim.fn.readfile(original), '\n')
      local have = table.concat(vim.fn.readfile(copy), '\n')
      if not have:find(want, 1, true) then
        table.insert(stale, name)
      end
    end
  end
  if #stale > 0 then
    health.warn('queries that differ from tree-sitter-rapid/queries: ' .. table.concat(stale, ', '), {
      'Run bash editors/sync-queries.sh in the repository.',
    })
  else
    health.ok('the queries are current and load')
  end
end

local function check_attached(rapid)
  health.start('rapid: the current buffer')
  local buf = vim.api.nvim_get_current_buf()
  -- :checkhealth opens its own buffer: look at the alternate one too
  local candidates = { buf, vim.fn.bufnr('#') }
  local rapid_buf
  for _, b in ipairs(candidates) do
    if b > 0 and vim.api.nvim_buf_is_valid(b) and vim.bo[b].filetype == 'rapid' then
      rapid_buf = b
      break
    end
  end
  if not rapid_buf then
    health.info('no RAPID buffer is current: open a module and run :checkhealth rapid again')
    return
  end
  local name = vim.api.nvim_buf_get_name(rapid_buf)
  local root = rapid.find_root(rapid_buf)
  if root then
    health.ok(('project root: %s'):format(root))
  else
    health.info(('no project root above %s (no rapid.toml, BACKINFO, SYSPAR, RAPID, .pgf or .git):'
      .. ' the server takes the file\'s task from its folder'):format(name))
  end
  local get = vim.lsp.get_clients or vim.lsp.get_active_clients
  local client = get({ bufnr = rapid_buf, name = 'rapid' })[1]
  if client then
    health.ok(('the server is attached (client %d, root %s)'):format(client.id,
      tostring(client.config.root_dir or client.root_dir or 'none')))
    local indentation = vim.b[rapid_buf].rapid_indentation
    if indentation then
      health.ok(('indentation from the server: %d columns per level, with %s'):format(indentation.width,
        indentation.tabs and 'tabs' or 'spaces'))
    end
  elseif rapid.config.lsp and rapid.server_binary() then
    health.warn('no rapid server is attached to ' .. name, { 'Run :RapidRestart, and see :LspLog.' })
  else
    health.warn('no rapid server is attached to ' .. name)
  end
end

function M.check()
  local ok, rapid = pcall(require, 'rapid')
  if not ok then
    health.error('the rapid plugin does not load: ' .. tostring(rapid))
    return
  end
  check_binary(rapid)
  check_parser(rapid)
  check_attached(rapid)
end

return M
