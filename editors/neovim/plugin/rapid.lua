-- ABB RAPID support: set up with defaults unless the user calls
-- require('rapid').setup(opts) (or sets vim.g.rapid_no_default_setup = true).
if vim.g.loaded_rapid then
  return
end
vim.g.loaded_rapid = true

if vim.fn.has('nvim-0.10') == 0 then
  vim.notify('rapid: Neovim 0.10 or later is needed', vim.log.levels.WARN)
  return
end

local rapid = require('rapid')
if not vim.g.rapid_no_default_setup then
  rapid.setup(vim.g.rapid_options)
end

vim.api.nvim_create_user_command('RapidBuildParser', function(args)
  local ok, result = pcall(rapid.build_parser, args.args ~= '' and args.args or nil)
  if not ok then
    vim.notify('rapid: building the parser failed: ' .. tostring(result), vim.log.levels.ERROR)
    return
  end
  vim.notify('rapid: built ' .. result)
  for _, buf in ipairs(vim.api.nvim_list_bufs()) do
    if vim.api.nvim_buf_is_loaded(buf) and vim.bo[buf].filetype == 'rapid' then
      rapid.attach(buf)
    end
  end
end, { nargs = '?', complete = 'dir', desc = 'Build the RAPID tree-sitter parser from tree-sitter-rapid/' })

vim.api.nvim_create_user_command('RapidRestart', function()
  rapid.restart()
end, { desc = 'Restart the rapid language server' })

vim.api.nvim_create_user_command('RapidDiff', function(args)
  require('rapid.diff').open(args.fargs)
end, {
  nargs = '+',
  complete = 'file',
  desc = 'Show what changed between a backup and the project (or two backups, or git revisions): rapid diff',
})

vim.api.nvim_create_user_command('RapidShowPath', function()
  require('rapid.dap').show()
end, { desc = "Open the robot's path of the current (or last) RAPID debug session in the browser" })
