-- Debugging RAPID with nvim-dap (`rapid dap`, the adapter VS Code uses) and
-- the robot's path following the debugger. Neovim cannot draw the page
-- itself: the adapter writes it (the page `rapid run --plot` writes, with
-- the arm) and rewrites it at each stop, with the script beside it that an
-- open page reads to follow; the first stop after the robot moved opens it
-- in the browser (vim.ui.open), and it follows from then on.
--
--   require('rapid.dap').setup({
--     robot = nil,        -- the `robot` launch argument of the default
--                         -- configuration ('IRB 1200-7/0.7'; nil: the task's own)
--     show_path = true,   -- open the path when the debugger first stops after a move
--   })
--   :RapidShowPath      opens the path of the current (or last) debug session
local M = {}

M.config = { robot = nil, show_path = true }

--- Sessions whose page was opened, by session id.
local opened = {}
--- The page of the last session that sent one.
M.last_page = nil

--- The path page of this Neovim's debug sessions (one file: a new session
--- rewrites it), in its cache folder.
---@return string
function M.page()
  local dir = vim.fs.joinpath(vim.fn.stdpath('cache'), 'rapid')
  vim.fn.mkdir(dir, 'p')
  return vim.fs.joinpath(dir, ('path-%d.html'):format(vim.fn.getpid()))
end

--- Opens a page in the browser.
---@param page string|nil
function M.show(page)
  page = page or M.last_page
  if not page or not vim.uv.fs_stat(page) then
    vim.notify('rapid: no path yet: debug a routine that moves the robot first', vim.log.levels.WARN)
    return
  end
  local _, err = vim.ui.open(page)
  if err then
    vim.notify('rapid: opening the path: ' .. err, vim.log.levels.ERROR)
  end
end

--- The `rapidPath` event of a session (`{ page, state }`, at each stop and
--- at the end): the first one after the robot moved opens the page, which
--- then follows the session by itself.
---@param session table|nil nvim-dap's session
---@param body table
function M.on_path(session, body)
  if type(body) ~= 'table' or type(body.page) ~= 'string' then
    return
  end
  M.last_page = body.page
  local id = session and session.id or 0
  local moves = type(body.state) == 'table' and body.state.moves or {}
  if opened[id] or not M.config.show_path or #moves == 0 then
    return
  end
  opened[id] = true
  M.show(body.page)
end

--- A launch configuration of the rapid type with the path page asked for.
---@param config table
---@return table
function M.with_page(config)
  if config.type == 'rapid' and config.request == 'launch' and config.plot == nil then
    config = vim.deepcopy(config)
    config.plot = M.page()
  end
  return config
end

--- Registers the adapter (unless one is), a default configuration (unless
--- there are some), the page for every rapid launch and the path's listener
--- with nvim-dap. Returns false when nvim-dap is not installed.
---@param opts table|nil
---@return boolean
function M.setup(opts)
  M.config = vim.tbl_extend('force', M.config, opts or {})
  local ok, dap = pcall(require, 'dap')
  if not ok then
    return false
  end
  local cmd = require('rapid').config.cmd
  local binary = type(cmd) == 'table' and cmd[1] or 'rapid'
  dap.adapters.rapid = dap.adapters.rapid or { type = 'executable', command = binary, args = { 'dap' } }
  dap.configurations.rapid = dap.configurations.rapid
    or {
      {
        type = 'rapid',
        request = 'launch',
        name = 'Run main',
        program = '${file}',
        entry = 'main',
        robot = M.config.robot,
      },
    }
  if dap.listeners.on_config then
    dap.listeners.on_config.rapid = M.with_page
  else
    for _, c in ipairs(dap.configurations.rapid) do
      c.plot = c.plot or M.page
    end
  end
  dap.listeners.after.event_rapidPath.rapid = M.on_path
  return true
end

return M
